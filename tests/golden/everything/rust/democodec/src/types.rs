//! Named types of the Demo protocol with every spec feature spec: enums (unknown values are kept), bitfields (named
//! accessors), structs and unions (selected by an earlier enum parameter).

/// Flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Flags(pub u16);

impl Flags {
    /// Mask of `ok` (bit 0).
    pub const OK: u16 = 0x0001;
    /// Mask of `level` (bits 12..=15).
    pub const LEVEL: u16 = 0xF000;
    /// Mask of `all` (bits 0..=15).
    pub const ALL: u16 = 0xFFFF;

    /// `ok` (bit 0).
    pub const fn ok(self) -> bool {
        self.0 & Self::OK != 0
    }

    /// Sets or clears `ok` (bit 0).
    pub fn set_ok(&mut self, v: bool) {
        if v {
            self.0 |= Self::OK;
        } else {
            self.0 &= !Self::OK;
        }
    }

    /// `level` (bits 12..=15).
    pub const fn level(self) -> u16 {
        (self.0 & Self::LEVEL) >> 12
    }

    /// Sets `level` (bits 12..=15); higher bits of `v` are ignored.
    pub fn set_level(&mut self, v: u16) {
        self.0 = (self.0 & !Self::LEVEL) | ((v << 12) & Self::LEVEL);
    }

    /// `all` (bits 0..=15).
    pub const fn all(self) -> u16 {
        self.0
    }

    /// Sets `all` (bits 0..=15); higher bits of `v` are ignored.
    pub fn set_all(&mut self, v: u16) {
        self.0 = v;
    }
}

impl crate::wire::Wire for Flags {
    const ZERO: Self = Self(0);
    const FIXED_SIZE: Option<usize> = <u16 as crate::wire::Wire>::FIXED_SIZE;

    #[inline(always)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        <u16 as crate::wire::Wire>::decode(r).map(Self)
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        self.0.encode(w)
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        self.0.write_json(w)
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Flags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Function.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Function(pub u8);

impl Function {
    pub const WRITE: Self = Self(1);
    pub const READ: Self = Self(2);
    pub const SAVE: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("write"),
            2 => Some("read"),
            3 => Some("save"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "write" => Some(Self::WRITE),
            "read" => Some(Self::READ),
            "save" => Some(Self::SAVE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for Function {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "Function({} {})", self.0, name),
            None => write!(f, "Function({})", self.0),
        }
    }
}

impl crate::wire::Wire for Function {
    const ZERO: Self = Self(0);
    const FIXED_SIZE: Option<usize> = <u8 as crate::wire::Wire>::FIXED_SIZE;

    #[inline(always)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        <u8 as crate::wire::Wire>::decode(r).map(Self)
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        self.0.encode(w)
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        self.0.write_json(w)
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Function {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GpioParams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioParams {
    pub pin: u8,
    pub polarity: bool,
}

impl Default for GpioParams {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioParams {
    const ZERO: Self = Self {
        pin: <u8 as crate::wire::Wire>::ZERO,
        polarity: <bool as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pin = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pin"))?;
        let p_polarity = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("polarity"))?;
        Ok(Self {
            pin: p_pin,
            polarity: p_polarity,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pin;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin"))?;
        let v = &self.polarity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("polarity"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pin;
        crate::json::key(w, &mut first, "pin")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.polarity;
        crate::json::key(w, &mut first, "polarity")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioParams {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["pin", "polarity"])?;
        let p_pin = o.req("pin", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_polarity = o.req("polarity", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            pin: p_pin,
            polarity: p_polarity,
        })
    }
}

/// Mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Mode(pub u8);

impl Mode {
    pub const NONE: Self = Self(0);
    pub const GPIO: Self = Self(1);
    pub const THRESHOLD: Self = Self(2);
    /// Devices: dev_a.
    pub const FAST: Self = Self(3);
    /// Devices: dev_b.
    pub const QUIET: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("gpio"),
            2 => Some("threshold"),
            3 => Some("fast"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "gpio" => Some(Self::GPIO),
            "threshold" => Some(Self::THRESHOLD),
            "fast" => Some(Self::FAST),
            "quiet" => Some(Self::QUIET),
            _ => None,
        }
    }
}

impl core::fmt::Debug for Mode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "Mode({} {})", self.0, name),
            None => write!(f, "Mode({})", self.0),
        }
    }
}

impl crate::wire::Wire for Mode {
    const ZERO: Self = Self(0);
    const FIXED_SIZE: Option<usize> = <u8 as crate::wire::Wire>::FIXED_SIZE;

    #[inline(always)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        <u8 as crate::wire::Wire>::decode(r).map(Self)
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        self.0.encode(w)
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        self.0.write_json(w)
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Mode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Signed.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Signed(pub i16);

impl Signed {
    pub const MINUS_ONE: Self = Self(-1);
    pub const PLUS_ONE: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            -1 => Some("minus_one"),
            1 => Some("plus_one"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "minus_one" => Some(Self::MINUS_ONE),
            "plus_one" => Some(Self::PLUS_ONE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for Signed {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "Signed({} {})", self.0, name),
            None => write!(f, "Signed({})", self.0),
        }
    }
}

impl crate::wire::Wire for Signed {
    const ZERO: Self = Self(0);
    const FIXED_SIZE: Option<usize> = <i16 as crate::wire::Wire>::FIXED_SIZE;

    #[inline(always)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        <i16 as crate::wire::Wire>::decode(r).map(Self)
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        self.0.encode(w)
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        self.0.write_json(w)
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Signed {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <i16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// ThresholdParams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThresholdParams {
    pub low: f64,
    pub high: f64,
    pub axes: [f32; 3],
}

impl Default for ThresholdParams {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ThresholdParams {
    const ZERO: Self = Self {
        low: <f64 as crate::wire::Wire>::ZERO,
        high: <f64 as crate::wire::Wire>::ZERO,
        axes: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(28);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_low = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low"))?;
        let p_high = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high"))?;
        let p_axes = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("axes"))?;
        Ok(Self {
            low: p_low,
            high: p_high,
            axes: p_axes,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.low;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("low"))?;
        let v = &self.high;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high"))?;
        let v = &self.axes;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("axes"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.low;
        crate::json::key(w, &mut first, "low")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high;
        crate::json::key(w, &mut first, "high")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.axes;
        crate::json::key(w, &mut first, "axes")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ThresholdParams {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["low", "high", "axes"])?;
        let p_low = o.req("low", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_high = o.req("high", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_axes = o.req("axes", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            low: p_low,
            high: p_high,
            axes: p_axes,
        })
    }
}

/// TriggerParams.
///
/// A union: the member is chosen by the value of an earlier selector parameter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TriggerParams {
    /// Selected by none (0).
    None,
    /// Selected by gpio (1).
    Gpio(crate::types::GpioParams),
    /// Selected by threshold (2).
    Threshold(crate::types::ThresholdParams),
}

impl TriggerParams {
    /// The first member with zero values.
    pub const ZERO: Self = Self::None;

    /// Selector value of this member.
    pub fn selector_value(&self) -> u8 {
        match self {
            Self::None => 0,
            Self::Gpio(_) => 1,
            Self::Threshold(_) => 2,
        }
    }

    /// Reads the member selected by `selector`.
    pub fn decode_selected(
        r: &mut crate::wire::Reader<'_>,
        selector: u8,
    ) -> Result<Self, crate::error::DecodeError> {
        match selector {
            0 => Ok(Self::None),
            1 => <crate::types::GpioParams as crate::wire::Wire>::decode(r).map(Self::Gpio),
            2 => {
                <crate::types::ThresholdParams as crate::wire::Wire>::decode(r).map(Self::Threshold)
            }
            value => {
                let _ = r;
                Err(crate::error::DecodeError::new(
                    crate::error::DecodeErrorKind::NoMember {
                        value: i128::from(value),
                    },
                ))
            }
        }
    }

    /// Writes the member after checking that `selector` chooses it.
    pub fn encode_selected(
        &self,
        w: &mut crate::wire::Writer<'_>,
        selector: u8,
    ) -> Result<(), crate::error::EncodeError> {
        if self.selector_value() != selector {
            return Err(crate::error::EncodeError::new(
                crate::error::EncodeErrorKind::UnionMismatch {
                    value: i128::from(selector),
                },
            ));
        }
        match self {
            Self::None => Ok(()),
            Self::Gpio(v) => crate::wire::Wire::encode(v, w),
            Self::Threshold(v) => crate::wire::Wire::encode(v, w),
        }
    }

    /// Writes the member's struct, or `null` for a member without data.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::None => w.write_str("null"),
            Self::Gpio(v) => crate::wire::Wire::write_json(v, w),
            Self::Threshold(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the member selected by `selector`.
    #[cfg(feature = "std")]
    pub fn from_json_selected(
        v: &crate::json_read::Json,
        selector: u8,
    ) -> Result<Self, crate::json_read::JsonError> {
        match selector {
            0 => crate::json_read::null(v).map(|()| Self::None),
            1 => <crate::types::GpioParams as crate::json_read::FromJson>::from_json(v)
                .map(Self::Gpio),
            2 => <crate::types::ThresholdParams as crate::json_read::FromJson>::from_json(v)
                .map(Self::Threshold),
            value => Err(crate::json_read::JsonError::new(std::format!(
                "no member for selector value {value}"
            ))),
        }
    }
}
