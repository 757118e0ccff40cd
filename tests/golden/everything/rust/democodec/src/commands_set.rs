//! Commands.
//!
//! Descriptor set 0x01 (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x01;

/// Ping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ping {}

impl Default for Ping {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Ping {
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
impl crate::json_read::FromJson for Ping {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl Ping {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for Ping {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "ping";
}

/// Configure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Configure {
    /// Function selector (sent first).
    pub function: crate::types::Function,
    /// Sent for: write, read, save.
    pub instance: u8,
    /// Sent for: write.
    pub mode: Option<crate::types::Mode>,
    /// Sent for: write.
    pub params: Option<crate::types::TriggerParams>,
    /// Sent for: write.
    pub suppress_ack: Option<bool>,
}

impl Default for Configure {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Configure {
    const ZERO: Self = Self {
        function: <crate::types::Function as crate::wire::Wire>::ZERO,
        instance: <u8 as crate::wire::Wire>::ZERO,
        mode: None,
        params: None,
        suppress_ack: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::Function as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_mode = if r.left() > 0 {
            Some(<crate::types::Mode as crate::wire::Wire>::decode(r).map_err(|e| e.at("mode"))?)
        } else {
            None
        };
        let p_params = if r.left() > 0 {
            Some(
                crate::types::TriggerParams::decode_selected(r, p_mode.map_or(0, |s| s.0))
                    .map_err(|e| e.at("params"))?,
            )
        } else {
            None
        };
        let p_suppress_ack = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("suppress_ack"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            instance: p_instance,
            mode: p_mode,
            params: p_params,
            suppress_ack: p_suppress_ack,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        if let Some(v) = &self.mode {
            optionals.present("mode")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        } else {
            optionals.absent("mode");
        }
        if let Some(v) = &self.params {
            optionals.present("params")?;
            v.encode_selected(w, self.mode.map_or(0, |s| s.0))
                .map_err(|e| e.at("params"))?;
        } else {
            optionals.absent("params");
        }
        if let Some(v) = &self.suppress_ack {
            optionals.present("suppress_ack")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("suppress_ack"))?;
        } else {
            optionals.absent("suppress_ack");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.mode {
            crate::json::key(w, &mut first, "mode")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.params {
            crate::json::key(w, &mut first, "params")?;
            v.write_json(w)?;
        }
        if let Some(v) = &self.suppress_ack {
            crate::json::key(w, &mut first, "suppress_ack")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Configure {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["function", "instance", "mode", "params", "suppress_ack"],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::Function as crate::json_read::FromJson>::from_json,
        )?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_mode = o.opt(
            "mode",
            <crate::types::Mode as crate::json_read::FromJson>::from_json,
        )?;
        let p_params = o.opt("params", |v| {
            crate::types::TriggerParams::from_json_selected(v, p_mode.map_or(0, |s| s.0))
        })?;
        let p_suppress_ack = o.opt(
            "suppress_ack",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            instance: p_instance,
            mode: p_mode,
            params: p_params,
            suppress_ack: p_suppress_ack,
        })
    }
}

impl Configure {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for Configure {
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "configure";
}

/// Configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Configuration {
    pub instance: u8,
    pub count: u8,
    pub rates: crate::bounded::BoundedVec<u16, 10>,
    pub name: crate::wire::Str<8>,
    pub label: crate::wire::Str<16>,
    pub matrix: [f64; 9],
    pub fixed: [i32; 4],
    pub flags: crate::types::Flags,
    pub signed: crate::types::Signed,
    pub tail: crate::bounded::BoundedVec<crate::wire::Char, 135>,
}

impl Default for Configuration {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Configuration {
    const ZERO: Self = Self {
        instance: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        rates: <crate::bounded::BoundedVec<u16, 10> as crate::wire::Wire>::ZERO,
        name: <crate::wire::Str<8> as crate::wire::Wire>::ZERO,
        label: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
        matrix: <[f64; 9] as crate::wire::Wire>::ZERO,
        fixed: <[i32; 4] as crate::wire::Wire>::ZERO,
        flags: <crate::types::Flags as crate::wire::Wire>::ZERO,
        signed: <crate::types::Signed as crate::wire::Wire>::ZERO,
        tail: <crate::bounded::BoundedVec<crate::wire::Char, 135> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_rates = crate::bounded::BoundedVec::<u16, 10>::decode_counted(r, u64::from(p_count))
            .map_err(|e| e.at("rates"))?;
        let p_name =
            <crate::wire::Str<8> as crate::wire::Wire>::decode(r).map_err(|e| e.at("name"))?;
        let p_label =
            <crate::wire::Str<16> as crate::wire::Wire>::decode(r).map_err(|e| e.at("label"))?;
        let p_matrix = <[f64; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("matrix"))?;
        let p_fixed = <[i32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("fixed"))?;
        let p_flags =
            <crate::types::Flags as crate::wire::Wire>::decode(r).map_err(|e| e.at("flags"))?;
        let p_signed =
            <crate::types::Signed as crate::wire::Wire>::decode(r).map_err(|e| e.at("signed"))?;
        let p_tail = crate::bounded::BoundedVec::<crate::wire::Char, 135>::decode_remaining(r)
            .map_err(|e| e.at("tail"))?;
        Ok(Self {
            instance: p_instance,
            count: p_count,
            rates: p_rates,
            name: p_name,
            label: p_label,
            matrix: p_matrix,
            fixed: p_fixed,
            flags: p_flags,
            signed: p_signed,
            tail: p_tail,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.rates;
        v.encode_counted(w, u64::from(self.count))
            .map_err(|e| e.at("rates"))?;
        let v = &self.name;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("name"))?;
        let v = &self.label;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("label"))?;
        let v = &self.matrix;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("matrix"))?;
        let v = &self.fixed;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("fixed"))?;
        let v = &self.flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        let v = &self.signed;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("signed"))?;
        let v = &self.tail;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tail"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.rates;
        crate::json::key(w, &mut first, "rates")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.name;
        crate::json::key(w, &mut first, "name")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.label;
        crate::json::key(w, &mut first, "label")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.matrix;
        crate::json::key(w, &mut first, "matrix")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.fixed;
        crate::json::key(w, &mut first, "fixed")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.flags;
        crate::json::key(w, &mut first, "flags")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.signed;
        crate::json::key(w, &mut first, "signed")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tail;
        crate::json::key(w, &mut first, "tail")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Configuration {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "instance", "count", "rates", "name", "label", "matrix", "fixed", "flags",
                "signed", "tail",
            ],
        )?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_rates = o.req(
            "rates",
            <crate::bounded::BoundedVec<u16, 10> as crate::json_read::FromJson>::from_json,
        )?;
        let p_name = o.req(
            "name",
            <crate::wire::Str<8> as crate::json_read::FromJson>::from_json,
        )?;
        let p_label = o.req(
            "label",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        let p_matrix = o.req(
            "matrix",
            <[f64; 9] as crate::json_read::FromJson>::from_json,
        )?;
        let p_fixed = o.req("fixed", <[i32; 4] as crate::json_read::FromJson>::from_json)?;
        let p_flags = o.req(
            "flags",
            <crate::types::Flags as crate::json_read::FromJson>::from_json,
        )?;
        let p_signed = o.req(
            "signed",
            <crate::types::Signed as crate::json_read::FromJson>::from_json,
        )?;
        let p_tail = o.req("tail", <crate::bounded::BoundedVec<crate::wire::Char, 135> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            instance: p_instance,
            count: p_count,
            rates: p_rates,
            name: p_name,
            label: p_label,
            matrix: p_matrix,
            fixed: p_fixed,
            flags: p_flags,
            signed: p_signed,
            tail: p_tail,
        })
    }
}

impl Configuration {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for Configuration {
    const DESCRIPTOR: u8 = 0x82;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "configuration";
}

/// Per-device command. Layout for device dev_a.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PerDeviceDevA {
    pub a: u32,
}

impl Default for PerDeviceDevA {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PerDeviceDevA {
    const ZERO: Self = Self {
        a: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_a = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("a"))?;
        Ok(Self { a: p_a })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.a;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.a;
        crate::json::key(w, &mut first, "a")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PerDeviceDevA {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["a"])?;
        let p_a = o.req("a", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { a: p_a })
    }
}

impl PerDeviceDevA {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for PerDeviceDevA {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "per_device";
}

/// Per-device command. Layout for device dev_b.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PerDeviceDevB {
    pub b: u64,
    pub extra: Option<u8>,
}

impl Default for PerDeviceDevB {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PerDeviceDevB {
    const ZERO: Self = Self {
        b: <u64 as crate::wire::Wire>::ZERO,
        extra: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_b = <u64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("b"))?;
        let p_extra = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("extra"))?)
        } else {
            None
        };
        Ok(Self {
            b: p_b,
            extra: p_extra,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.b;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("b"))?;
        if let Some(v) = &self.extra {
            optionals.present("extra")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("extra"))?;
        } else {
            optionals.absent("extra");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.b;
        crate::json::key(w, &mut first, "b")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.extra {
            crate::json::key(w, &mut first, "extra")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PerDeviceDevB {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["b", "extra"])?;
        let p_b = o.req("b", <u64 as crate::json_read::FromJson>::from_json)?;
        let p_extra = o.opt("extra", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            b: p_b,
            extra: p_extra,
        })
    }
}

impl PerDeviceDevB {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for PerDeviceDevB {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "per_device";
}

/// Per-device command.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PerDevice {
    /// Layout for device `dev_a`.
    DevA(PerDeviceDevA),
    /// Layout for device `dev_b`.
    DevB(PerDeviceDevB),
}

impl PerDevice {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x03;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "per_device";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::DevA(_) => crate::Device::DevA,
            Self::DevB(_) => crate::Device::DevB,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::DevA) {
            return <PerDeviceDevA as crate::wire::Layout>::decode_data(data).map(Self::DevA);
        }
        if device == Some(crate::Device::DevB) {
            return <PerDeviceDevB as crate::wire::Layout>::decode_data(data).map(Self::DevB);
        }
        let first = match <PerDeviceDevA as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::DevA(v)),
            Err(e) => e,
        };
        if let Ok(v) = <PerDeviceDevB as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::DevB(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::DevA(v) => crate::wire::Layout::encode_data(v, w),
            Self::DevB(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::DevA(v) => crate::wire::Wire::write_json(v, w),
            Self::DevB(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::DevA) => {
                <PerDeviceDevA as crate::json_read::FromJson>::from_json(values)
                    .map(Self::DevA)
                    .map_err(|e| e.at("values"))
            }
            Some(crate::Device::DevB) => {
                <PerDeviceDevB as crate::json_read::FromJson>::from_json(values)
                    .map(Self::DevB)
                    .map_err(|e| e.at("values"))
            }
            None => Err(crate::json_read::JsonError::new(
                "field per_device has per-device layouts; name one with \"device\" (dev_a, dev_b)",
            )
            .at("device")),
        }
    }
}

/// A decoded field of set 0x01 (`commands`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `ping` (0x01).
    Ping(Ping),
    /// `configure` (0x02).
    Configure(Configure),
    /// `configuration` (0x82).
    Configuration(Configuration),
    /// `per_device` (0x03).
    PerDevice(PerDevice),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::Ping(_) => 0x01,
            Self::Configure(_) => 0x02,
            Self::Configuration(_) => 0x82,
            Self::PerDevice(_) => 0x03,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Ping(_) => "ping",
            Self::Configure(_) => "configure",
            Self::Configuration(_) => "configuration",
            Self::PerDevice(_) => "per_device",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::Ping(_) => None,
            Self::Configure(_) => None,
            Self::Configuration(_) => None,
            Self::PerDevice(v) => Some(v.device()),
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Ping(v) => crate::wire::Layout::encode_data(v, w),
            Self::Configure(v) => crate::wire::Layout::encode_data(v, w),
            Self::Configuration(v) => crate::wire::Layout::encode_data(v, w),
            Self::PerDevice(v) => v.encode_data(w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Ping(v) => crate::wire::Wire::write_json(v, w),
            Self::Configure(v) => crate::wire::Wire::write_json(v, w),
            Self::Configuration(v) => crate::wire::Wire::write_json(v, w),
            Self::PerDevice(v) => v.write_json(w),
        }
    }

    /// Decodes field `descriptor` of this set; `None` if the set has no such field.
    pub fn decode(
        descriptor: u8,
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        match descriptor {
            0x01 => Some(<Ping as crate::wire::Layout>::decode_data(data).map(Self::Ping)),
            0x02 => {
                Some(<Configure as crate::wire::Layout>::decode_data(data).map(Self::Configure))
            }
            0x82 => Some(
                <Configuration as crate::wire::Layout>::decode_data(data).map(Self::Configuration),
            ),
            0x03 => Some(PerDevice::decode_data(data, device).map(Self::PerDevice)),
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
                        <Ping as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Ping),
            ),
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Configure as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Configure),
            ),
            0x82 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Configuration as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Configuration),
            ),
            0x03 => Some(PerDevice::from_json(device, values).map(Self::PerDevice)),
            _ => None,
        }
    }
}
