//! IMU Configuration Messages. Configure the serial baud rate, digital filter, output decimation, output contents, sensor ranges, data output and external trigger; save, load or reset all settings.
//!
//! Descriptor set 0x02 (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x02;

/// UART baud rate configure. Set, read, save, load or reset the baud rate. Messages after the reply use the new rate; saving may delay the reply while the setting is written to flash.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UartBaudRate {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// New baud rate. Units: baud. Sent for: write.
    pub baud_rate: Option<crate::types::BaudRate>,
}

impl Default for UartBaudRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for UartBaudRate {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        baud_rate: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_baud_rate = if r.left() > 0 {
            Some(
                <crate::types::BaudRate as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("baud_rate"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            baud_rate: p_baud_rate,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.baud_rate {
            optionals.present("baud_rate")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("baud_rate"))?;
        } else {
            optionals.absent("baud_rate");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.baud_rate {
            crate::json::key(w, &mut first, "baud_rate")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for UartBaudRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "baud_rate"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_baud_rate = o.opt(
            "baud_rate",
            <crate::types::BaudRate as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            baud_rate: p_baud_rate,
        })
    }
}

impl UartBaudRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for UartBaudRate {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "uart_baud_rate";
}

/// UART baud rate (read reply, inferred). Current baud rate, in reply to "Request current settings".
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UartBaudRateResponse {
    /// Current baud rate. Units: baud.
    pub baud_rate: crate::types::BaudRate,
}

impl Default for UartBaudRateResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for UartBaudRateResponse {
    const ZERO: Self = Self {
        baud_rate: <crate::types::BaudRate as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_baud_rate = <crate::types::BaudRate as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("baud_rate"))?;
        Ok(Self {
            baud_rate: p_baud_rate,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.baud_rate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("baud_rate"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.baud_rate;
        crate::json::key(w, &mut first, "baud_rate")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for UartBaudRateResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["baud_rate"])?;
        let p_baud_rate = o.req(
            "baud_rate",
            <crate::types::BaudRate as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            baud_rate: p_baud_rate,
        })
    }
}

impl UartBaudRateResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for UartBaudRateResponse {
    const DESCRIPTOR: u8 = 0x81;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "uart_baud_rate_response";
}

/// Configure filter. Set, read, save, load or reset the internal digital filter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Filter {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Filter bandwidth control code. Sent for: write.
    pub bandwidth: Option<crate::types::FilterBandwidth>,
}

impl Default for Filter {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Filter {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        bandwidth: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_bandwidth = if r.left() > 0 {
            Some(
                <crate::types::FilterBandwidth as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("bandwidth"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            bandwidth: p_bandwidth,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.bandwidth {
            optionals.present("bandwidth")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("bandwidth"))?;
        } else {
            optionals.absent("bandwidth");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.bandwidth {
            crate::json::key(w, &mut first, "bandwidth")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Filter {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "bandwidth"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_bandwidth = o.opt(
            "bandwidth",
            <crate::types::FilterBandwidth as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            bandwidth: p_bandwidth,
        })
    }
}

impl Filter {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for Filter {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "filter";
}

/// Filter (read reply, inferred). Current filter bandwidth control code.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterResponse {
    /// Filter bandwidth control code.
    pub bandwidth: crate::types::FilterBandwidth,
}

impl Default for FilterResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FilterResponse {
    const ZERO: Self = Self {
        bandwidth: <crate::types::FilterBandwidth as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bandwidth = <crate::types::FilterBandwidth as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("bandwidth"))?;
        Ok(Self {
            bandwidth: p_bandwidth,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bandwidth;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bandwidth"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.bandwidth;
        crate::json::key(w, &mut first, "bandwidth")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FilterResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["bandwidth"])?;
        let p_bandwidth = o.req(
            "bandwidth",
            <crate::types::FilterBandwidth as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            bandwidth: p_bandwidth,
        })
    }
}

impl FilterResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for FilterResponse {
    const DESCRIPTOR: u8 = 0x83;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "filter_response";
}

/// IMU sample rate configure. Set, read, save, load or reset the output decimation: the output rate is the internal sample rate (0x0206) divided by the decimation (800 Hz / 8 = 100 Hz).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleRate {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Divider of the internal sample rate. Sent for: write.
    pub decimation: Option<u16>,
}

impl Default for SampleRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SampleRate {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        decimation: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_decimation = if r.left() > 0 {
            Some(<u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("decimation"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            decimation: p_decimation,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.decimation {
            optionals.present("decimation")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("decimation"))?;
        } else {
            optionals.absent("decimation");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.decimation {
            crate::json::key(w, &mut first, "decimation")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SampleRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "decimation"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_decimation = o.opt("decimation", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            decimation: p_decimation,
        })
    }
}

impl SampleRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for SampleRate {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "sample_rate";
}

/// IMU sample rate (read reply, inferred). Current output decimation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleRateResponse {
    /// Divider of the internal sample rate.
    pub decimation: u16,
}

impl Default for SampleRateResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SampleRateResponse {
    const ZERO: Self = Self {
        decimation: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_decimation = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("decimation"))?;
        Ok(Self {
            decimation: p_decimation,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.decimation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("decimation"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.decimation;
        crate::json::key(w, &mut first, "decimation")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SampleRateResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["decimation"])?;
        let p_decimation = o.req("decimation", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            decimation: p_decimation,
        })
    }
}

impl SampleRateResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for SampleRateResponse {
    const DESCRIPTOR: u8 = 0x84;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "sample_rate_response";
}

/// Select sensors (Rev A). Choose the measurements the IMU data message (0xA2) carries, by their data codes. Its size byte is one less than its data on the wire, which the device expects (Select Sensors errata); Select Sensors Rev B (0x020C) is the corrected message.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SelectSensors {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Reserved for future use (0x00). Sent for: write.
    pub reserved: Option<u8>,
    /// Measurements to output, in order. Sent for: write.
    pub sensors: Option<crate::bounded::BoundedVec<crate::types::SensorCode, 251>>,
}

impl Default for SelectSensors {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SelectSensors {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        reserved: None,
        sensors: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_reserved = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?)
        } else {
            None
        };
        let p_sensors = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<crate::types::SensorCode, 251>::decode_remaining(r)
                    .map_err(|e| e.at("sensors"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            reserved: p_reserved,
            sensors: p_sensors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.reserved {
            optionals.present("reserved")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        } else {
            optionals.absent("reserved");
        }
        if let Some(v) = &self.sensors {
            optionals.present("sensors")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensors"))?;
        } else {
            optionals.absent("sensors");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.reserved {
            crate::json::key(w, &mut first, "reserved")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.sensors {
            crate::json::key(w, &mut first, "sensors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SelectSensors {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "reserved", "sensors"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved = o.opt("reserved", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_sensors = o.opt("sensors", <crate::bounded::BoundedVec<crate::types::SensorCode, 251> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            reserved: p_reserved,
            sensors: p_sensors,
        })
    }
}

impl SelectSensors {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for SelectSensors {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "select_sensors";
}

/// Select sensors (read reply, inferred). The selected measurements.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SelectSensorsResponse {
    /// Selected measurements.
    pub sensors: crate::bounded::BoundedVec<crate::types::SensorCode, 253>,
}

impl Default for SelectSensorsResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SelectSensorsResponse {
    const ZERO: Self = Self {
        sensors:
            <crate::bounded::BoundedVec<crate::types::SensorCode, 253> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_sensors =
            crate::bounded::BoundedVec::<crate::types::SensorCode, 253>::decode_remaining(r)
                .map_err(|e| e.at("sensors"))?;
        Ok(Self { sensors: p_sensors })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.sensors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.sensors;
        crate::json::key(w, &mut first, "sensors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SelectSensorsResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["sensors"])?;
        let p_sensors = o.req("sensors", <crate::bounded::BoundedVec<crate::types::SensorCode, 253> as crate::json_read::FromJson>::from_json)?;
        Ok(Self { sensors: p_sensors })
    }
}

impl SelectSensorsResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for SelectSensorsResponse {
    const DESCRIPTOR: u8 = 0x85;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "select_sensors_response";
}

/// Get IMU internal sample rate. Ask for the internal sample rate that the decimation divides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetInternalSampleRate {}

impl Default for GetInternalSampleRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetInternalSampleRate {
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
impl crate::json_read::FromJson for GetInternalSampleRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetInternalSampleRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for GetInternalSampleRate {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "get_internal_sample_rate";
}

/// IMU internal sample rate. The internal sample rate in hertz.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InternalSampleRate {
    /// Internal sample rate (e.g. 800). Units: Hz.
    pub rate: u16,
}

impl Default for InternalSampleRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for InternalSampleRate {
    const ZERO: Self = Self {
        rate: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_rate = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("rate"))?;
        Ok(Self { rate: p_rate })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.rate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("rate"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.rate;
        crate::json::key(w, &mut first, "rate")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for InternalSampleRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["rate"])?;
        let p_rate = o.req("rate", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { rate: p_rate })
    }
}

impl InternalSampleRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for InternalSampleRate {
    const DESCRIPTOR: u8 = 0x86;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "internal_sample_rate";
}

/// Config accel range. Set, read, save, load or reset the accelerometer dynamic range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelRange {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Accelerometer range code. Sent for: write.
    pub range: Option<crate::types::AccelRange>,
}

impl Default for AccelRange {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelRange {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        range: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_range = if r.left() > 0 {
            Some(
                <crate::types::AccelRange as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("range"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            range: p_range,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.range {
            optionals.present("range")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("range"))?;
        } else {
            optionals.absent("range");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.range {
            crate::json::key(w, &mut first, "range")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelRange {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "range"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_range = o.opt(
            "range",
            <crate::types::AccelRange as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            range: p_range,
        })
    }
}

impl AccelRange {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for AccelRange {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "accel_range";
}

/// Accel range (read reply, inferred). Current accelerometer range code.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelRangeResponse {
    /// Accelerometer range code.
    pub range: crate::types::AccelRange,
}

impl Default for AccelRangeResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelRangeResponse {
    const ZERO: Self = Self {
        range: <crate::types::AccelRange as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_range = <crate::types::AccelRange as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("range"))?;
        Ok(Self { range: p_range })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.range;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("range"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.range;
        crate::json::key(w, &mut first, "range")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelRangeResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["range"])?;
        let p_range = o.req(
            "range",
            <crate::types::AccelRange as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { range: p_range })
    }
}

impl AccelRangeResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for AccelRangeResponse {
    const DESCRIPTOR: u8 = 0x87;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "accel_range_response";
}

/// Configure gyro range. Set, read, save, load or reset the gyroscope dynamic range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroRange {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Gyroscope range code. Sent for: write.
    pub range: Option<crate::types::GyroRange>,
}

impl Default for GyroRange {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroRange {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        range: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_range = if r.left() > 0 {
            Some(
                <crate::types::GyroRange as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("range"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            range: p_range,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.range {
            optionals.present("range")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("range"))?;
        } else {
            optionals.absent("range");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.range {
            crate::json::key(w, &mut first, "range")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroRange {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "range"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_range = o.opt(
            "range",
            <crate::types::GyroRange as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            range: p_range,
        })
    }
}

impl GyroRange {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for GyroRange {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "gyro_range";
}

/// Gyro range (read reply, inferred). Current gyroscope range code.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroRangeResponse {
    /// Gyroscope range code.
    pub range: crate::types::GyroRange,
}

impl Default for GyroRangeResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroRangeResponse {
    const ZERO: Self = Self {
        range: <crate::types::GyroRange as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_range =
            <crate::types::GyroRange as crate::wire::Wire>::decode(r).map_err(|e| e.at("range"))?;
        Ok(Self { range: p_range })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.range;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("range"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.range;
        crate::json::key(w, &mut first, "range")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroRangeResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["range"])?;
        let p_range = o.req(
            "range",
            <crate::types::GyroRange as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { range: p_range })
    }
}

impl GyroRangeResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for GyroRangeResponse {
    const DESCRIPTOR: u8 = 0x88;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "gyro_range_response";
}

/// Configure all. Save, load or reset to factory defaults every configurable setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConfigAll {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
}

impl Default for ConfigAll {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ConfigAll {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        Ok(Self {
            function: p_function,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ConfigAll {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
        })
    }
}

impl ConfigAll {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for ConfigAll {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "config_all";
}

/// Data on/off. Enable or disable the data output.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DataOnOff {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Data on or off. Sent for: write.
    pub control: Option<crate::types::OnOff>,
}

impl Default for DataOnOff {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DataOnOff {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        control: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_control = if r.left() > 0 {
            Some(
                <crate::types::OnOff as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("control"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            control: p_control,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.control {
            optionals.present("control")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("control"))?;
        } else {
            optionals.absent("control");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.control {
            crate::json::key(w, &mut first, "control")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DataOnOff {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "control"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_control = o.opt(
            "control",
            <crate::types::OnOff as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            control: p_control,
        })
    }
}

impl DataOnOff {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for DataOnOff {
    const DESCRIPTOR: u8 = 0x0A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "data_on_off";
}

/// Data on/off (read reply, inferred). Whether data output is on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DataOnOffResponse {
    /// Data on or off.
    pub control: crate::types::OnOff,
}

impl Default for DataOnOffResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DataOnOffResponse {
    const ZERO: Self = Self {
        control: <crate::types::OnOff as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_control =
            <crate::types::OnOff as crate::wire::Wire>::decode(r).map_err(|e| e.at("control"))?;
        Ok(Self { control: p_control })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.control;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("control"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.control;
        crate::json::key(w, &mut first, "control")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DataOnOffResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["control"])?;
        let p_control = o.req(
            "control",
            <crate::types::OnOff as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { control: p_control })
    }
}

impl DataOnOffResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for DataOnOffResponse {
    const DESCRIPTOR: u8 = 0x8A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "data_on_off_response";
}

/// XTRIG on/off. Enable or disable the external trigger input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct XtrigOnOff {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// External trigger on or off. Sent for: write.
    pub control: Option<crate::types::OnOff>,
}

impl Default for XtrigOnOff {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for XtrigOnOff {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        control: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_control = if r.left() > 0 {
            Some(
                <crate::types::OnOff as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("control"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            control: p_control,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.control {
            optionals.present("control")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("control"))?;
        } else {
            optionals.absent("control");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.control {
            crate::json::key(w, &mut first, "control")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for XtrigOnOff {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "control"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_control = o.opt(
            "control",
            <crate::types::OnOff as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            control: p_control,
        })
    }
}

impl XtrigOnOff {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for XtrigOnOff {
    const DESCRIPTOR: u8 = 0x0B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "xtrig_on_off";
}

/// XTRIG on/off (read reply, inferred). Whether the external trigger input is on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct XtrigOnOffResponse {
    /// External trigger on or off.
    pub control: crate::types::OnOff,
}

impl Default for XtrigOnOffResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for XtrigOnOffResponse {
    const ZERO: Self = Self {
        control: <crate::types::OnOff as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_control =
            <crate::types::OnOff as crate::wire::Wire>::decode(r).map_err(|e| e.at("control"))?;
        Ok(Self { control: p_control })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.control;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("control"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.control;
        crate::json::key(w, &mut first, "control")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for XtrigOnOffResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["control"])?;
        let p_control = o.req(
            "control",
            <crate::types::OnOff as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { control: p_control })
    }
}

impl XtrigOnOffResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for XtrigOnOffResponse {
    const DESCRIPTOR: u8 = 0x8B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "xtrig_on_off_response";
}

/// Select sensors (Rev B). Choose the measurements the IMU data message (0xA2) carries, by their data codes; the corrected Select Sensors (size byte counts every data byte, no reserved byte).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SelectSensorsRevB {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Measurements to output, in order. Sent for: write.
    pub sensors: Option<crate::bounded::BoundedVec<crate::types::SensorCode, 252>>,
}

impl Default for SelectSensorsRevB {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SelectSensorsRevB {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        sensors: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_sensors = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<crate::types::SensorCode, 252>::decode_remaining(r)
                    .map_err(|e| e.at("sensors"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            sensors: p_sensors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.sensors {
            optionals.present("sensors")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensors"))?;
        } else {
            optionals.absent("sensors");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.sensors {
            crate::json::key(w, &mut first, "sensors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SelectSensorsRevB {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "sensors"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_sensors = o.opt("sensors", <crate::bounded::BoundedVec<crate::types::SensorCode, 252> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            sensors: p_sensors,
        })
    }
}

impl SelectSensorsRevB {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for SelectSensorsRevB {
    const DESCRIPTOR: u8 = 0x0C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "select_sensors_rev_b";
}

/// Select sensors Rev B (read reply, inferred). The selected measurements.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SelectSensorsRevBResponse {
    /// Selected measurements.
    pub sensors: crate::bounded::BoundedVec<crate::types::SensorCode, 253>,
}

impl Default for SelectSensorsRevBResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SelectSensorsRevBResponse {
    const ZERO: Self = Self {
        sensors:
            <crate::bounded::BoundedVec<crate::types::SensorCode, 253> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_sensors =
            crate::bounded::BoundedVec::<crate::types::SensorCode, 253>::decode_remaining(r)
                .map_err(|e| e.at("sensors"))?;
        Ok(Self { sensors: p_sensors })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.sensors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.sensors;
        crate::json::key(w, &mut first, "sensors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SelectSensorsRevBResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["sensors"])?;
        let p_sensors = o.req("sensors", <crate::bounded::BoundedVec<crate::types::SensorCode, 253> as crate::json_read::FromJson>::from_json)?;
        Ok(Self { sensors: p_sensors })
    }
}

impl SelectSensorsRevBResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for SelectSensorsRevBResponse {
    const DESCRIPTOR: u8 = 0x8C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "select_sensors_rev_b_response";
}

/// Config aux accel range. Set, read, save, load or reset the auxiliary accelerometer dynamic range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AuxAccelRange {
    /// Function selector (sent first).
    pub function: crate::types::FunctionCode,
    /// Auxiliary accelerometer range code. Sent for: write.
    pub range: Option<crate::types::AccelRange>,
}

impl Default for AuxAccelRange {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AuxAccelRange {
    const ZERO: Self = Self {
        function: <crate::types::FunctionCode as crate::wire::Wire>::ZERO,
        range: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_range = if r.left() > 0 {
            Some(
                <crate::types::AccelRange as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("range"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            range: p_range,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.range {
            optionals.present("range")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("range"))?;
        } else {
            optionals.absent("range");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.range {
            crate::json::key(w, &mut first, "range")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AuxAccelRange {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "range"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionCode as crate::json_read::FromJson>::from_json,
        )?;
        let p_range = o.opt(
            "range",
            <crate::types::AccelRange as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            range: p_range,
        })
    }
}

impl AuxAccelRange {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for AuxAccelRange {
    const DESCRIPTOR: u8 = 0x0D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "aux_accel_range";
}

/// Aux accel range (read reply, inferred). Current auxiliary accelerometer range code.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AuxAccelRangeResponse {
    /// Auxiliary accelerometer range code.
    pub range: crate::types::AccelRange,
}

impl Default for AuxAccelRangeResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AuxAccelRangeResponse {
    const ZERO: Self = Self {
        range: <crate::types::AccelRange as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_range = <crate::types::AccelRange as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("range"))?;
        Ok(Self { range: p_range })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.range;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("range"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.range;
        crate::json::key(w, &mut first, "range")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AuxAccelRangeResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["range"])?;
        let p_range = o.req(
            "range",
            <crate::types::AccelRange as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { range: p_range })
    }
}

impl AuxAccelRangeResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x02;
}

impl crate::wire::Layout for AuxAccelRangeResponse {
    const DESCRIPTOR: u8 = 0x8D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x02);
    const NAME: &'static str = "aux_accel_range_response";
}

/// A decoded field of set 0x02 (`imu_config`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `uart_baud_rate` (0x01).
    UartBaudRate(UartBaudRate),
    /// `uart_baud_rate_response` (0x81).
    UartBaudRateResponse(UartBaudRateResponse),
    /// `filter` (0x03).
    Filter(Filter),
    /// `filter_response` (0x83).
    FilterResponse(FilterResponse),
    /// `sample_rate` (0x04).
    SampleRate(SampleRate),
    /// `sample_rate_response` (0x84).
    SampleRateResponse(SampleRateResponse),
    /// `select_sensors` (0x05).
    SelectSensors(SelectSensors),
    /// `select_sensors_response` (0x85).
    SelectSensorsResponse(SelectSensorsResponse),
    /// `get_internal_sample_rate` (0x06).
    GetInternalSampleRate(GetInternalSampleRate),
    /// `internal_sample_rate` (0x86).
    InternalSampleRate(InternalSampleRate),
    /// `accel_range` (0x07).
    AccelRange(AccelRange),
    /// `accel_range_response` (0x87).
    AccelRangeResponse(AccelRangeResponse),
    /// `gyro_range` (0x08).
    GyroRange(GyroRange),
    /// `gyro_range_response` (0x88).
    GyroRangeResponse(GyroRangeResponse),
    /// `config_all` (0x09).
    ConfigAll(ConfigAll),
    /// `data_on_off` (0x0A).
    DataOnOff(DataOnOff),
    /// `data_on_off_response` (0x8A).
    DataOnOffResponse(DataOnOffResponse),
    /// `xtrig_on_off` (0x0B).
    XtrigOnOff(XtrigOnOff),
    /// `xtrig_on_off_response` (0x8B).
    XtrigOnOffResponse(XtrigOnOffResponse),
    /// `select_sensors_rev_b` (0x0C).
    SelectSensorsRevB(SelectSensorsRevB),
    /// `select_sensors_rev_b_response` (0x8C).
    SelectSensorsRevBResponse(SelectSensorsRevBResponse),
    /// `aux_accel_range` (0x0D).
    AuxAccelRange(AuxAccelRange),
    /// `aux_accel_range_response` (0x8D).
    AuxAccelRangeResponse(AuxAccelRangeResponse),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::UartBaudRate(_) => 0x01,
            Self::UartBaudRateResponse(_) => 0x81,
            Self::Filter(_) => 0x03,
            Self::FilterResponse(_) => 0x83,
            Self::SampleRate(_) => 0x04,
            Self::SampleRateResponse(_) => 0x84,
            Self::SelectSensors(_) => 0x05,
            Self::SelectSensorsResponse(_) => 0x85,
            Self::GetInternalSampleRate(_) => 0x06,
            Self::InternalSampleRate(_) => 0x86,
            Self::AccelRange(_) => 0x07,
            Self::AccelRangeResponse(_) => 0x87,
            Self::GyroRange(_) => 0x08,
            Self::GyroRangeResponse(_) => 0x88,
            Self::ConfigAll(_) => 0x09,
            Self::DataOnOff(_) => 0x0A,
            Self::DataOnOffResponse(_) => 0x8A,
            Self::XtrigOnOff(_) => 0x0B,
            Self::XtrigOnOffResponse(_) => 0x8B,
            Self::SelectSensorsRevB(_) => 0x0C,
            Self::SelectSensorsRevBResponse(_) => 0x8C,
            Self::AuxAccelRange(_) => 0x0D,
            Self::AuxAccelRangeResponse(_) => 0x8D,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::UartBaudRate(_) => "uart_baud_rate",
            Self::UartBaudRateResponse(_) => "uart_baud_rate_response",
            Self::Filter(_) => "filter",
            Self::FilterResponse(_) => "filter_response",
            Self::SampleRate(_) => "sample_rate",
            Self::SampleRateResponse(_) => "sample_rate_response",
            Self::SelectSensors(_) => "select_sensors",
            Self::SelectSensorsResponse(_) => "select_sensors_response",
            Self::GetInternalSampleRate(_) => "get_internal_sample_rate",
            Self::InternalSampleRate(_) => "internal_sample_rate",
            Self::AccelRange(_) => "accel_range",
            Self::AccelRangeResponse(_) => "accel_range_response",
            Self::GyroRange(_) => "gyro_range",
            Self::GyroRangeResponse(_) => "gyro_range_response",
            Self::ConfigAll(_) => "config_all",
            Self::DataOnOff(_) => "data_on_off",
            Self::DataOnOffResponse(_) => "data_on_off_response",
            Self::XtrigOnOff(_) => "xtrig_on_off",
            Self::XtrigOnOffResponse(_) => "xtrig_on_off_response",
            Self::SelectSensorsRevB(_) => "select_sensors_rev_b",
            Self::SelectSensorsRevBResponse(_) => "select_sensors_rev_b_response",
            Self::AuxAccelRange(_) => "aux_accel_range",
            Self::AuxAccelRangeResponse(_) => "aux_accel_range_response",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::UartBaudRate(_) => None,
            Self::UartBaudRateResponse(_) => None,
            Self::Filter(_) => None,
            Self::FilterResponse(_) => None,
            Self::SampleRate(_) => None,
            Self::SampleRateResponse(_) => None,
            Self::SelectSensors(_) => None,
            Self::SelectSensorsResponse(_) => None,
            Self::GetInternalSampleRate(_) => None,
            Self::InternalSampleRate(_) => None,
            Self::AccelRange(_) => None,
            Self::AccelRangeResponse(_) => None,
            Self::GyroRange(_) => None,
            Self::GyroRangeResponse(_) => None,
            Self::ConfigAll(_) => None,
            Self::DataOnOff(_) => None,
            Self::DataOnOffResponse(_) => None,
            Self::XtrigOnOff(_) => None,
            Self::XtrigOnOffResponse(_) => None,
            Self::SelectSensorsRevB(_) => None,
            Self::SelectSensorsRevBResponse(_) => None,
            Self::AuxAccelRange(_) => None,
            Self::AuxAccelRangeResponse(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::UartBaudRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::UartBaudRateResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::Filter(v) => crate::wire::Layout::encode_data(v, w),
            Self::FilterResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SampleRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::SampleRateResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SelectSensors(v) => crate::wire::Layout::encode_data(v, w),
            Self::SelectSensorsResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetInternalSampleRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::InternalSampleRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelRange(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelRangeResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroRange(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroRangeResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::ConfigAll(v) => crate::wire::Layout::encode_data(v, w),
            Self::DataOnOff(v) => crate::wire::Layout::encode_data(v, w),
            Self::DataOnOffResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::XtrigOnOff(v) => crate::wire::Layout::encode_data(v, w),
            Self::XtrigOnOffResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SelectSensorsRevB(v) => crate::wire::Layout::encode_data(v, w),
            Self::SelectSensorsRevBResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AuxAccelRange(v) => crate::wire::Layout::encode_data(v, w),
            Self::AuxAccelRangeResponse(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::UartBaudRate(v) => crate::wire::Wire::write_json(v, w),
            Self::UartBaudRateResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::Filter(v) => crate::wire::Wire::write_json(v, w),
            Self::FilterResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SampleRate(v) => crate::wire::Wire::write_json(v, w),
            Self::SampleRateResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SelectSensors(v) => crate::wire::Wire::write_json(v, w),
            Self::SelectSensorsResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GetInternalSampleRate(v) => crate::wire::Wire::write_json(v, w),
            Self::InternalSampleRate(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelRange(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelRangeResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroRange(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroRangeResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::ConfigAll(v) => crate::wire::Wire::write_json(v, w),
            Self::DataOnOff(v) => crate::wire::Wire::write_json(v, w),
            Self::DataOnOffResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::XtrigOnOff(v) => crate::wire::Wire::write_json(v, w),
            Self::XtrigOnOffResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SelectSensorsRevB(v) => crate::wire::Wire::write_json(v, w),
            Self::SelectSensorsRevBResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AuxAccelRange(v) => crate::wire::Wire::write_json(v, w),
            Self::AuxAccelRangeResponse(v) => crate::wire::Wire::write_json(v, w),
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
                <UartBaudRate as crate::wire::Layout>::decode_data(data).map(Self::UartBaudRate),
            ),
            0x81 => Some(
                <UartBaudRateResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::UartBaudRateResponse),
            ),
            0x03 => Some(<Filter as crate::wire::Layout>::decode_data(data).map(Self::Filter)),
            0x83 => Some(
                <FilterResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::FilterResponse),
            ),
            0x04 => {
                Some(<SampleRate as crate::wire::Layout>::decode_data(data).map(Self::SampleRate))
            }
            0x84 => Some(
                <SampleRateResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SampleRateResponse),
            ),
            0x05 => Some(
                <SelectSensors as crate::wire::Layout>::decode_data(data).map(Self::SelectSensors),
            ),
            0x85 => Some(
                <SelectSensorsResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SelectSensorsResponse),
            ),
            0x06 => Some(
                <GetInternalSampleRate as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetInternalSampleRate),
            ),
            0x86 => Some(
                <InternalSampleRate as crate::wire::Layout>::decode_data(data)
                    .map(Self::InternalSampleRate),
            ),
            0x07 => {
                Some(<AccelRange as crate::wire::Layout>::decode_data(data).map(Self::AccelRange))
            }
            0x87 => Some(
                <AccelRangeResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelRangeResponse),
            ),
            0x08 => {
                Some(<GyroRange as crate::wire::Layout>::decode_data(data).map(Self::GyroRange))
            }
            0x88 => Some(
                <GyroRangeResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GyroRangeResponse),
            ),
            0x09 => {
                Some(<ConfigAll as crate::wire::Layout>::decode_data(data).map(Self::ConfigAll))
            }
            0x0A => {
                Some(<DataOnOff as crate::wire::Layout>::decode_data(data).map(Self::DataOnOff))
            }
            0x8A => Some(
                <DataOnOffResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::DataOnOffResponse),
            ),
            0x0B => {
                Some(<XtrigOnOff as crate::wire::Layout>::decode_data(data).map(Self::XtrigOnOff))
            }
            0x8B => Some(
                <XtrigOnOffResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::XtrigOnOffResponse),
            ),
            0x0C => Some(
                <SelectSensorsRevB as crate::wire::Layout>::decode_data(data)
                    .map(Self::SelectSensorsRevB),
            ),
            0x8C => Some(
                <SelectSensorsRevBResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SelectSensorsRevBResponse),
            ),
            0x0D => Some(
                <AuxAccelRange as crate::wire::Layout>::decode_data(data).map(Self::AuxAccelRange),
            ),
            0x8D => Some(
                <AuxAccelRangeResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AuxAccelRangeResponse),
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
                        <UartBaudRate as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::UartBaudRate),
            ),
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <UartBaudRateResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::UartBaudRateResponse),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Filter as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Filter),
            ),
            0x83 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FilterResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::FilterResponse),
            ),
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SampleRate as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SampleRate),
            ),
            0x84 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SampleRateResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SampleRateResponse),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SelectSensors as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SelectSensors),
            ),
            0x85 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SelectSensorsResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SelectSensorsResponse),
            ),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetInternalSampleRate as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetInternalSampleRate),
            ),
            0x86 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <InternalSampleRate as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::InternalSampleRate),
            ),
            0x07 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelRange as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelRange),
            ),
            0x87 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelRangeResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelRangeResponse),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroRange as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroRange),
            ),
            0x88 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroRangeResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroRangeResponse),
            ),
            0x09 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ConfigAll as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ConfigAll),
            ),
            0x0A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DataOnOff as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DataOnOff),
            ),
            0x8A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DataOnOffResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DataOnOffResponse),
            ),
            0x0B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <XtrigOnOff as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::XtrigOnOff),
            ),
            0x8B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <XtrigOnOffResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::XtrigOnOffResponse),
            ),
            0x0C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SelectSensorsRevB as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SelectSensorsRevB),
            ),
            0x8C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SelectSensorsRevBResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SelectSensorsRevBResponse),
            ),
            0x0D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AuxAccelRange as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AuxAccelRange),
            ),
            0x8D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AuxAccelRangeResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AuxAccelRangeResponse),
            ),
            _ => None,
        }
    }
}
