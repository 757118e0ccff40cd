//! Named types of the MicroStrain MIP spec: enums (unknown values are kept), bitfields (named
//! accessors), structs and unions (selected by an earlier enum parameter).

/// Ack/Nack code. Second byte of the ack/nack field; 0 is an ACK, any other value a NACK giving the reason.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AckCode(pub u8);

impl AckCode {
    /// Success (ACK).
    pub const OK: Self = Self(0);
    /// The command descriptor is not supported by this device.
    pub const UNKNOWN_COMMAND: Self = Self(1);
    /// An otherwise complete packet has a bad checksum (GX5-45: invalid checksum).
    pub const BAD_CHECKSUM: Self = Self(2);
    /// One or more parameters are invalid: out of the allowed range, or not the expected size or type.
    pub const INVALID_PARAMETER: Self = Self(3);
    /// Device could not complete the command.
    pub const COMMAND_FAILED: Self = Self(4);
    /// Device could not complete the command within the expected time.
    pub const COMMAND_TIMEOUT: Self = Self(5);
    /// Unknown descriptor set (CV7 only). Devices: cv7_ins.
    pub const UNKNOWN_DESCRIPTOR_SET: Self = Self(6);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("ok"),
            1 => Some("unknown_command"),
            2 => Some("bad_checksum"),
            3 => Some("invalid_parameter"),
            4 => Some("command_failed"),
            5 => Some("command_timeout"),
            6 => Some("unknown_descriptor_set"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "ok" => Some(Self::OK),
            "unknown_command" => Some(Self::UNKNOWN_COMMAND),
            "bad_checksum" => Some(Self::BAD_CHECKSUM),
            "invalid_parameter" => Some(Self::INVALID_PARAMETER),
            "command_failed" => Some(Self::COMMAND_FAILED),
            "command_timeout" => Some(Self::COMMAND_TIMEOUT),
            "unknown_descriptor_set" => Some(Self::UNKNOWN_DESCRIPTOR_SET),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AckCode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AckCode({} {})", self.0, name),
            None => write!(f, "AckCode({})", self.0),
        }
    }
}

impl crate::wire::Wire for AckCode {
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
impl crate::json_read::FromJson for AckCode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO action mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ActionGpioMode(pub u8);

impl ActionGpioMode {
    /// Pin state will not be changed.
    pub const DISABLED: Self = Self(0);
    /// High while the trigger is active, low otherwise.
    pub const ACTIVE_HIGH: Self = Self(1);
    /// Low while the trigger is active, high otherwise.
    pub const ACTIVE_LOW: Self = Self(2);
    /// Set high each time the trigger activates.
    pub const ONESHOT_HIGH: Self = Self(5);
    /// Set low each time the trigger activates.
    pub const ONESHOT_LOW: Self = Self(6);
    /// Toggle each time the trigger activates.
    pub const TOGGLE: Self = Self(7);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("disabled"),
            1 => Some("active_high"),
            2 => Some("active_low"),
            5 => Some("oneshot_high"),
            6 => Some("oneshot_low"),
            7 => Some("toggle"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "disabled" => Some(Self::DISABLED),
            "active_high" => Some(Self::ACTIVE_HIGH),
            "active_low" => Some(Self::ACTIVE_LOW),
            "oneshot_high" => Some(Self::ONESHOT_HIGH),
            "oneshot_low" => Some(Self::ONESHOT_LOW),
            "toggle" => Some(Self::TOGGLE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for ActionGpioMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "ActionGpioMode({} {})", self.0, name),
            None => write!(f, "ActionGpioMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for ActionGpioMode {
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
impl crate::json_read::FromJson for ActionGpioMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// ActionGpioParams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActionGpioParams {
    /// GPIO pin number.
    pub pin: u8,
    /// Behavior of the pin.
    pub mode: crate::types::ActionGpioMode,
}

impl Default for ActionGpioParams {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ActionGpioParams {
    const ZERO: Self = Self {
        pin: <u8 as crate::wire::Wire>::ZERO,
        mode: <crate::types::ActionGpioMode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pin = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pin"))?;
        let p_mode = <crate::types::ActionGpioMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        Ok(Self {
            pin: p_pin,
            mode: p_mode,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pin;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin"))?;
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pin;
        crate::json::key(w, &mut first, "pin")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ActionGpioParams {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["pin", "mode"])?;
        let p_pin = o.req("pin", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_mode = o.req(
            "mode",
            <crate::types::ActionGpioMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            pin: p_pin,
            mode: p_mode,
        })
    }
}

/// ActionParams.
///
/// A union: the member is chosen by the value of an earlier selector parameter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ActionParams {
    /// Selected by none (0).
    None,
    /// Selected by gpio (1).
    Gpio(crate::types::ActionGpioParams),
    /// Selected by message (2).
    Message(crate::types::MessageParams),
}

impl ActionParams {
    /// The first member with zero values.
    pub const ZERO: Self = Self::None;

    /// Selector value of this member.
    pub fn selector_value(&self) -> u8 {
        match self {
            Self::None => 0,
            Self::Gpio(_) => 1,
            Self::Message(_) => 2,
        }
    }

    /// Reads the member selected by `selector`.
    pub fn decode_selected(
        r: &mut crate::wire::Reader<'_>,
        selector: u8,
    ) -> Result<Self, crate::error::DecodeError> {
        match selector {
            0 => Ok(Self::None),
            1 => <crate::types::ActionGpioParams as crate::wire::Wire>::decode(r).map(Self::Gpio),
            2 => <crate::types::MessageParams as crate::wire::Wire>::decode(r).map(Self::Message),
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
            Self::Message(v) => crate::wire::Wire::encode(v, w),
        }
    }

    /// Writes the member's struct, or `null` for a member without data.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::None => w.write_str("null"),
            Self::Gpio(v) => crate::wire::Wire::write_json(v, w),
            Self::Message(v) => crate::wire::Wire::write_json(v, w),
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
            1 => <crate::types::ActionGpioParams as crate::json_read::FromJson>::from_json(v)
                .map(Self::Gpio),
            2 => <crate::types::MessageParams as crate::json_read::FromJson>::from_json(v)
                .map(Self::Message),
            value => Err(crate::json_read::JsonError::new(std::format!(
                "no member for selector value {value}"
            ))),
        }
    }
}

/// ActionStatusEntry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActionStatusEntry {
    /// Configured action type.
    pub action_type: crate::types::ActionType,
    /// Associated trigger instance.
    pub trigger_id: u8,
}

impl Default for ActionStatusEntry {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ActionStatusEntry {
    const ZERO: Self = Self {
        action_type: <crate::types::ActionType as crate::wire::Wire>::ZERO,
        trigger_id: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_action_type = <crate::types::ActionType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("action_type"))?;
        let p_trigger_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("trigger_id"))?;
        Ok(Self {
            action_type: p_action_type,
            trigger_id: p_trigger_id,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.action_type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("action_type"))?;
        let v = &self.trigger_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("trigger_id"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.action_type;
        crate::json::key(w, &mut first, "action_type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.trigger_id;
        crate::json::key(w, &mut first, "trigger_id")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ActionStatusEntry {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["action_type", "trigger_id"])?;
        let p_action_type = o.req(
            "action_type",
            <crate::types::ActionType as crate::json_read::FromJson>::from_json,
        )?;
        let p_trigger_id = o.req("trigger_id", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            action_type: p_action_type,
            trigger_id: p_trigger_id,
        })
    }
}

/// Event action type.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ActionType(pub u8);

impl ActionType {
    /// No action. Parameters should be empty.
    pub const NONE: Self = Self(0);
    /// Control the state of a GPIO pin.
    pub const GPIO: Self = Self(1);
    /// Output a data packet.
    pub const MESSAGE: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("gpio"),
            2 => Some("message"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "gpio" => Some(Self::GPIO),
            "message" => Some(Self::MESSAGE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for ActionType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "ActionType({} {})", self.0, name),
            None => write!(f, "ActionType({})", self.0),
        }
    }
}

impl crate::wire::Wire for ActionType {
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
impl crate::json_read::FromJson for ActionType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Auto-adaptive filter operating level.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AdaptiveFilterLevel(pub u8);

impl AdaptiveFilterLevel {
    /// Adaptive filtering off.
    pub const OFF: Self = Self(0);
    /// Conservative.
    pub const CONSERVATIVE: Self = Self(1);
    /// Moderate (default).
    pub const MODERATE: Self = Self(2);
    /// Aggressive.
    pub const AGGRESSIVE: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("off"),
            1 => Some("conservative"),
            2 => Some("moderate"),
            3 => Some("aggressive"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "off" => Some(Self::OFF),
            "conservative" => Some(Self::CONSERVATIVE),
            "moderate" => Some(Self::MODERATE),
            "aggressive" => Some(Self::AGGRESSIVE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AdaptiveFilterLevel {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AdaptiveFilterLevel({} {})", self.0, name),
            None => write!(f, "AdaptiveFilterLevel({})", self.0),
        }
    }
}

impl crate::wire::Wire for AdaptiveFilterLevel {
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
impl crate::json_read::FromJson for AdaptiveFilterLevel {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Adaptive measurement mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AdaptiveMeasurementMode(pub u8);

impl AdaptiveMeasurementMode {
    /// No adaptive measurement.
    pub const DISABLED: Self = Self(0);
    /// Fixed adaptive measurement using the specified filter and limit parameters.
    pub const FIXED: Self = Self(1);
    /// Auto-adaptive: the Kalman filter re-weights the measurement by its perceived quality (3DM-GX5 and later); limits are ignored.
    pub const AUTO: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("disabled"),
            1 => Some("fixed"),
            2 => Some("auto"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "disabled" => Some(Self::DISABLED),
            "fixed" => Some(Self::FIXED),
            "auto" => Some(Self::AUTO),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AdaptiveMeasurementMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AdaptiveMeasurementMode({} {})", self.0, name),
            None => write!(f, "AdaptiveMeasurementMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for AdaptiveMeasurementMode {
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
impl crate::json_read::FromJson for AdaptiveMeasurementMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding command echo mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AidingEchoMode(pub u8);

impl AidingEchoMode {
    /// The aiding measurement commands are not acknowledged.
    pub const SUPPRESS_ACK: Self = Self(0);
    /// Normal ack/nack behavior.
    pub const STANDARD: Self = Self(1);
    /// The device echoes the aiding data back as a response.
    pub const RESPONSE: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("suppress_ack"),
            1 => Some("standard"),
            2 => Some("response"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "suppress_ack" => Some(Self::SUPPRESS_ACK),
            "standard" => Some(Self::STANDARD),
            "response" => Some(Self::RESPONSE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AidingEchoMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AidingEchoMode({} {})", self.0, name),
            None => write!(f, "AidingEchoMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for AidingEchoMode {
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
impl crate::json_read::FromJson for AidingEchoMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding frame rotation as Euler angles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingFrameEuler {
    /// Roll, pitch, yaw of the frame relative to the vehicle frame, each within +/- pi. Units: rad.
    pub euler: [f32; 3],
}

impl Default for AidingFrameEuler {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingFrameEuler {
    const ZERO: Self = Self {
        euler: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_euler = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("euler"))?;
        Ok(Self { euler: p_euler })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.euler;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("euler"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.euler;
        crate::json::key(w, &mut first, "euler")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingFrameEuler {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["euler"])?;
        let p_euler = o.req("euler", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { euler: p_euler })
    }
}

/// Aiding frame rotation format.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AidingFrameFormat(pub u8);

impl AidingFrameFormat {
    /// Translation vector followed by Euler angles (roll, pitch, yaw).
    pub const EULER: Self = Self(1);
    /// Translation vector followed by a quaternion (w, x, y, z).
    pub const QUATERNION: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("euler"),
            2 => Some("quaternion"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "euler" => Some(Self::EULER),
            "quaternion" => Some(Self::QUATERNION),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AidingFrameFormat {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AidingFrameFormat({} {})", self.0, name),
            None => write!(f, "AidingFrameFormat({})", self.0),
        }
    }
}

impl crate::wire::Wire for AidingFrameFormat {
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
impl crate::json_read::FromJson for AidingFrameFormat {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding frame rotation as a quaternion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingFrameQuaternion {
    /// Rotation of the frame relative to the vehicle frame, (w, x, y, z).
    pub quaternion: [f32; 4],
}

impl Default for AidingFrameQuaternion {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingFrameQuaternion {
    const ZERO: Self = Self {
        quaternion: <[f32; 4] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_quaternion =
            <[f32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("quaternion"))?;
        Ok(Self {
            quaternion: p_quaternion,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.quaternion;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("quaternion"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.quaternion;
        crate::json::key(w, &mut first, "quaternion")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingFrameQuaternion {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["quaternion"])?;
        let p_quaternion = o.req(
            "quaternion",
            <[f32; 4] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            quaternion: p_quaternion,
        })
    }
}

/// Aiding frame rotation. Rotation of an aiding frame, as Euler angles or as a quaternion depending on the format.
///
/// A union: the member is chosen by the value of an earlier selector parameter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AidingFrameRotation {
    /// Selected by euler (1).
    Euler(crate::types::AidingFrameEuler),
    /// Selected by quaternion (2).
    Quaternion(crate::types::AidingFrameQuaternion),
}

impl AidingFrameRotation {
    /// The first member with zero values.
    pub const ZERO: Self = Self::Euler(<crate::types::AidingFrameEuler as crate::wire::Wire>::ZERO);

    /// Selector value of this member.
    pub fn selector_value(&self) -> u8 {
        match self {
            Self::Euler(_) => 1,
            Self::Quaternion(_) => 2,
        }
    }

    /// Reads the member selected by `selector`.
    pub fn decode_selected(
        r: &mut crate::wire::Reader<'_>,
        selector: u8,
    ) -> Result<Self, crate::error::DecodeError> {
        match selector {
            1 => <crate::types::AidingFrameEuler as crate::wire::Wire>::decode(r).map(Self::Euler),
            2 => <crate::types::AidingFrameQuaternion as crate::wire::Wire>::decode(r)
                .map(Self::Quaternion),
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
            Self::Euler(v) => crate::wire::Wire::encode(v, w),
            Self::Quaternion(v) => crate::wire::Wire::encode(v, w),
        }
    }

    /// Writes the member's struct, or `null` for a member without data.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Euler(v) => crate::wire::Wire::write_json(v, w),
            Self::Quaternion(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the member selected by `selector`.
    #[cfg(feature = "std")]
    pub fn from_json_selected(
        v: &crate::json_read::Json,
        selector: u8,
    ) -> Result<Self, crate::json_read::JsonError> {
        match selector {
            1 => <crate::types::AidingFrameEuler as crate::json_read::FromJson>::from_json(v)
                .map(Self::Euler),
            2 => <crate::types::AidingFrameQuaternion as crate::json_read::FromJson>::from_json(v)
                .map(Self::Quaternion),
            value => Err(crate::json_read::JsonError::new(std::format!(
                "no member for selector value {value}"
            ))),
        }
    }
}

/// LLH position aiding valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct AidingLlhValidFlags(pub u16);

impl AidingLlhValidFlags {
    /// Mask of `latitude` (bit 0).
    pub const LATITUDE: u16 = 0x0001;
    /// Mask of `longitude` (bit 1).
    pub const LONGITUDE: u16 = 0x0002;
    /// Mask of `height` (bit 2).
    pub const HEIGHT: u16 = 0x0004;

    /// Latitude valid. (bit 0)
    pub const fn latitude(self) -> bool {
        self.0 & Self::LATITUDE != 0
    }

    /// Sets or clears `latitude` (bit 0).
    pub fn set_latitude(&mut self, v: bool) {
        if v {
            self.0 |= Self::LATITUDE;
        } else {
            self.0 &= !Self::LATITUDE;
        }
    }

    /// Longitude valid. (bit 1)
    pub const fn longitude(self) -> bool {
        self.0 & Self::LONGITUDE != 0
    }

    /// Sets or clears `longitude` (bit 1).
    pub fn set_longitude(&mut self, v: bool) {
        if v {
            self.0 |= Self::LONGITUDE;
        } else {
            self.0 &= !Self::LONGITUDE;
        }
    }

    /// Height valid. (bit 2)
    pub const fn height(self) -> bool {
        self.0 & Self::HEIGHT != 0
    }

    /// Sets or clears `height` (bit 2).
    pub fn set_height(&mut self, v: bool) {
        if v {
            self.0 |= Self::HEIGHT;
        } else {
            self.0 &= !Self::HEIGHT;
        }
    }
}

impl crate::wire::Wire for AidingLlhValidFlags {
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
impl crate::json_read::FromJson for AidingLlhValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding measurement source.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AidingMeasurementSource(pub u16);

impl AidingMeasurementSource {
    /// GNSS position and velocity.
    pub const GNSS_POS_VEL: Self = Self(0);
    /// GNSS heading (dual antenna).
    pub const GNSS_HEADING: Self = Self(1);
    /// Pressure altimeter (built-in sensor).
    pub const ALTIMETER: Self = Self(2);
    /// Speed sensor / odometer.
    pub const SPEED: Self = Self(3);
    /// Magnetometer (built-in sensor).
    pub const MAGNETOMETER: Self = Self(4);
    /// External heading input.
    pub const EXTERNAL_HEADING: Self = Self(5);
    /// External pressure altimeter input.
    pub const EXTERNAL_ALTIMETER: Self = Self(6);
    /// External magnetometer input.
    pub const EXTERNAL_MAGNETOMETER: Self = Self(7);
    /// External body frame velocity input.
    pub const BODY_FRAME_VEL: Self = Self(8);
    /// All sources (for save, load and default).
    pub const ALL: Self = Self(65535);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("gnss_pos_vel"),
            1 => Some("gnss_heading"),
            2 => Some("altimeter"),
            3 => Some("speed"),
            4 => Some("magnetometer"),
            5 => Some("external_heading"),
            6 => Some("external_altimeter"),
            7 => Some("external_magnetometer"),
            8 => Some("body_frame_vel"),
            65535 => Some("all"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "gnss_pos_vel" => Some(Self::GNSS_POS_VEL),
            "gnss_heading" => Some(Self::GNSS_HEADING),
            "altimeter" => Some(Self::ALTIMETER),
            "speed" => Some(Self::SPEED),
            "magnetometer" => Some(Self::MAGNETOMETER),
            "external_heading" => Some(Self::EXTERNAL_HEADING),
            "external_altimeter" => Some(Self::EXTERNAL_ALTIMETER),
            "external_magnetometer" => Some(Self::EXTERNAL_MAGNETOMETER),
            "body_frame_vel" => Some(Self::BODY_FRAME_VEL),
            "all" => Some(Self::ALL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AidingMeasurementSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AidingMeasurementSource({} {})", self.0, name),
            None => write!(f, "AidingMeasurementSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for AidingMeasurementSource {
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
impl crate::json_read::FromJson for AidingMeasurementSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding measurement timestamp. Timestamp carried first in every aiding measurement command.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingTime {
    /// Clock of the timestamp.
    pub timebase: crate::types::AidingTimebase,
    /// Reserved.
    pub reserved: u8,
    /// Time of the measurement in nanoseconds, in the timebase's clock. Units: ns.
    pub nanoseconds: u64,
}

impl Default for AidingTime {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingTime {
    const ZERO: Self = Self {
        timebase: <crate::types::AidingTimebase as crate::wire::Wire>::ZERO,
        reserved: <u8 as crate::wire::Wire>::ZERO,
        nanoseconds: <u64 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(10);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_timebase = <crate::types::AidingTimebase as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("timebase"))?;
        let p_reserved = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?;
        let p_nanoseconds =
            <u64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("nanoseconds"))?;
        Ok(Self {
            timebase: p_timebase,
            reserved: p_reserved,
            nanoseconds: p_nanoseconds,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.timebase;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("timebase"))?;
        let v = &self.reserved;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        let v = &self.nanoseconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("nanoseconds"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.timebase;
        crate::json::key(w, &mut first, "timebase")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved;
        crate::json::key(w, &mut first, "reserved")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.nanoseconds;
        crate::json::key(w, &mut first, "nanoseconds")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingTime {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["timebase", "reserved", "nanoseconds"])?;
        let p_timebase = o.req(
            "timebase",
            <crate::types::AidingTimebase as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved = o.req("reserved", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_nanoseconds = o.req(
            "nanoseconds",
            <u64 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            timebase: p_timebase,
            reserved: p_reserved,
            nanoseconds: p_nanoseconds,
        })
    }
}

/// Aiding measurement timebase. Clock in which the timestamp of an aiding measurement is expressed.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AidingTimebase(pub u8);

impl AidingTimebase {
    /// Timestamp in the device's internal reference time (nanoseconds since power-on).
    pub const INTERNAL_REFERENCE: Self = Self(1);
    /// Timestamp in external time, synchronised by the PPS source and GPS time update.
    pub const EXTERNAL_TIME: Self = Self(2);
    /// No timestamp: the measurement is taken at its arrival time, with a fixed latency.
    pub const TIME_OF_ARRIVAL: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("internal_reference"),
            2 => Some("external_time"),
            3 => Some("time_of_arrival"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "internal_reference" => Some(Self::INTERNAL_REFERENCE),
            "external_time" => Some(Self::EXTERNAL_TIME),
            "time_of_arrival" => Some(Self::TIME_OF_ARRIVAL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AidingTimebase {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AidingTimebase({} {})", self.0, name),
            None => write!(f, "AidingTimebase({})", self.0),
        }
    }
}

impl crate::wire::Wire for AidingTimebase {
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
impl crate::json_read::FromJson for AidingTimebase {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding vector valid flags. Which axes of a 3-axis aiding measurement are valid; axes with 0 are ignored.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct AidingVectorValidFlags(pub u16);

impl AidingVectorValidFlags {
    /// Mask of `x` (bit 0).
    pub const X: u16 = 0x0001;
    /// Mask of `y` (bit 1).
    pub const Y: u16 = 0x0002;
    /// Mask of `z` (bit 2).
    pub const Z: u16 = 0x0004;

    /// X (or north) component valid. (bit 0)
    pub const fn x(self) -> bool {
        self.0 & Self::X != 0
    }

    /// Sets or clears `x` (bit 0).
    pub fn set_x(&mut self, v: bool) {
        if v {
            self.0 |= Self::X;
        } else {
            self.0 &= !Self::X;
        }
    }

    /// Y (or east) component valid. (bit 1)
    pub const fn y(self) -> bool {
        self.0 & Self::Y != 0
    }

    /// Sets or clears `y` (bit 1).
    pub fn set_y(&mut self, v: bool) {
        if v {
            self.0 |= Self::Y;
        } else {
            self.0 &= !Self::Y;
        }
    }

    /// Z (or down) component valid. (bit 2)
    pub const fn z(self) -> bool {
        self.0 & Self::Z != 0
    }

    /// Sets or clears `z` (bit 2).
    pub fn set_z(&mut self, v: bool) {
        if v {
            self.0 |= Self::Z;
        } else {
            self.0 &= !Self::Z;
        }
    }
}

impl crate::wire::Wire for AidingVectorValidFlags {
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
impl crate::json_read::FromJson for AidingVectorValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Altitude aiding source.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AltitudeAidingSource(pub u8);

impl AltitudeAidingSource {
    /// No altitude aiding (disabled).
    pub const NONE: Self = Self(0);
    /// Pressure sensor aiding enabled.
    pub const PRESSURE: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("pressure"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "pressure" => Some(Self::PRESSURE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AltitudeAidingSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AltitudeAidingSource({} {})", self.0, name),
            None => write!(f, "AltitudeAidingSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for AltitudeAidingSource {
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
impl crate::json_read::FromJson for AltitudeAidingSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Assisted fix option.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AssistedFixOption(pub u8);

impl AssistedFixOption {
    /// No assisted fix (default).
    pub const NONE: Self = Self(0);
    /// Assisted fix enabled.
    pub const ENABLED: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("enabled"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "enabled" => Some(Self::ENABLED),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AssistedFixOption {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AssistedFixOption({} {})", self.0, name),
            None => write!(f, "AssistedFixOption({})", self.0),
        }
    }
}

impl crate::wire::Wire for AssistedFixOption {
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
impl crate::json_read::FromJson for AssistedFixOption {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// CombinationParams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CombinationParams {
    /// Last column of the truth table of the inputs.
    pub logic_table: u16,
    /// Trigger IDs of the inputs; 0 for unused inputs.
    pub input_triggers: [u8; 4],
}

impl Default for CombinationParams {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CombinationParams {
    const ZERO: Self = Self {
        logic_table: <u16 as crate::wire::Wire>::ZERO,
        input_triggers: <[u8; 4] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_logic_table =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("logic_table"))?;
        let p_input_triggers =
            <[u8; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("input_triggers"))?;
        Ok(Self {
            logic_table: p_logic_table,
            input_triggers: p_input_triggers,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.logic_table;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("logic_table"))?;
        let v = &self.input_triggers;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("input_triggers"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.logic_table;
        crate::json::key(w, &mut first, "logic_table")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.input_triggers;
        crate::json::key(w, &mut first, "input_triggers")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CombinationParams {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["logic_table", "input_triggers"])?;
        let p_logic_table = o.req(
            "logic_table",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_input_triggers = o.req(
            "input_triggers",
            <[u8; 4] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            logic_table: p_logic_table,
            input_triggers: p_input_triggers,
        })
    }
}

/// GNSS constellation option flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ConstellationOptions(pub u16);

impl ConstellationOptions {
    /// Mask of `l1saif` (bit 0).
    pub const L1SAIF: u16 = 0x0001;

    /// L1SAIF signal (QZSS only). (bit 0)
    pub const fn l1saif(self) -> bool {
        self.0 & Self::L1SAIF != 0
    }

    /// Sets or clears `l1saif` (bit 0).
    pub fn set_l1saif(&mut self, v: bool) {
        if v {
            self.0 |= Self::L1SAIF;
        } else {
            self.0 &= !Self::L1SAIF;
        }
    }
}

impl crate::wire::Wire for ConstellationOptions {
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
impl crate::json_read::FromJson for ConstellationOptions {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS constellation configuration entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstellationSettings {
    /// Constellation.
    pub constellation_id: crate::types::Gx5ConstellationId,
    /// 0x00 disable, 0x01 enable.
    pub enable: u8,
    /// Tracking channels reserved for this constellation (0-32; all constellations together at most 32).
    pub reserved_channels: u8,
    /// Maximum tracking channels for this constellation (0-32, not below reserved_channels).
    pub max_channels: u8,
    /// Constellation options.
    pub option_flags: crate::types::ConstellationOptions,
}

impl Default for ConstellationSettings {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ConstellationSettings {
    const ZERO: Self = Self {
        constellation_id: <crate::types::Gx5ConstellationId as crate::wire::Wire>::ZERO,
        enable: <u8 as crate::wire::Wire>::ZERO,
        reserved_channels: <u8 as crate::wire::Wire>::ZERO,
        max_channels: <u8 as crate::wire::Wire>::ZERO,
        option_flags: <crate::types::ConstellationOptions as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_constellation_id = <crate::types::Gx5ConstellationId as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("constellation_id"))?;
        let p_enable = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        let p_reserved_channels =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved_channels"))?;
        let p_max_channels =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_channels"))?;
        let p_option_flags = <crate::types::ConstellationOptions as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("option_flags"))?;
        Ok(Self {
            constellation_id: p_constellation_id,
            enable: p_enable,
            reserved_channels: p_reserved_channels,
            max_channels: p_max_channels,
            option_flags: p_option_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.constellation_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("constellation_id"))?;
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        let v = &self.reserved_channels;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved_channels"))?;
        let v = &self.max_channels;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_channels"))?;
        let v = &self.option_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("option_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.constellation_id;
        crate::json::key(w, &mut first, "constellation_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved_channels;
        crate::json::key(w, &mut first, "reserved_channels")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.max_channels;
        crate::json::key(w, &mut first, "max_channels")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.option_flags;
        crate::json::key(w, &mut first, "option_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ConstellationSettings {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "constellation_id",
                "enable",
                "reserved_channels",
                "max_channels",
                "option_flags",
            ],
        )?;
        let p_constellation_id = o.req(
            "constellation_id",
            <crate::types::Gx5ConstellationId as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.req("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_reserved_channels = o.req(
            "reserved_channels",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_max_channels = o.req(
            "max_channels",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_option_flags = o.req(
            "option_flags",
            <crate::types::ConstellationOptions as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            constellation_id: p_constellation_id,
            enable: p_enable,
            reserved_channels: p_reserved_channels,
            max_channels: p_max_channels,
            option_flags: p_option_flags,
        })
    }
}

/// 3DM-CV7 commanded built-in test result.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7BitFlags(pub u32);

impl Cv7BitFlags {
    /// Mask of `general_hardware_fault` (bit 0).
    pub const GENERAL_HARDWARE_FAULT: u32 = 0x00000001;
    /// Mask of `general_firmware_fault` (bit 1).
    pub const GENERAL_FIRMWARE_FAULT: u32 = 0x00000002;
    /// Mask of `timing_overload` (bit 2).
    pub const TIMING_OVERLOAD: u32 = 0x00000004;
    /// Mask of `buffer_overrun` (bit 3).
    pub const BUFFER_OVERRUN: u32 = 0x00000008;
    /// Mask of `reserved_system` (bits 4..=7).
    pub const RESERVED_SYSTEM: u32 = 0x000000F0;
    /// Mask of `reserved_comms` (bits 8..=11).
    pub const RESERVED_COMMS: u32 = 0x00000F00;
    /// Mask of `accelerometer_fault` (bit 12).
    pub const ACCELEROMETER_FAULT: u32 = 0x00001000;
    /// Mask of `gyroscope_fault` (bit 13).
    pub const GYROSCOPE_FAULT: u32 = 0x00002000;
    /// Mask of `magnetometer_fault` (bit 14).
    pub const MAGNETOMETER_FAULT: u32 = 0x00004000;
    /// Mask of `pressure_sensor_fault` (bit 15).
    pub const PRESSURE_SENSOR_FAULT: u32 = 0x00008000;
    /// Mask of `reserved_imu` (bits 16..=17).
    pub const RESERVED_IMU: u32 = 0x00030000;
    /// Mask of `calibration_error` (bit 18).
    pub const CALIBRATION_ERROR: u32 = 0x00040000;
    /// Mask of `general_imu_fault` (bit 19).
    pub const GENERAL_IMU_FAULT: u32 = 0x00080000;
    /// Mask of `reserved_filter` (bits 20..=21).
    pub const RESERVED_FILTER: u32 = 0x00300000;
    /// Mask of `filter_solution_fault` (bit 22).
    pub const FILTER_SOLUTION_FAULT: u32 = 0x00400000;
    /// Mask of `general_filter_fault` (bit 23).
    pub const GENERAL_FILTER_FAULT: u32 = 0x00800000;
    /// Mask of `reserved` (bits 24..=31).
    pub const RESERVED: u32 = 0xFF000000;

    /// A critical hardware component has failed or is not operating properly. (bit 0)
    pub const fn general_hardware_fault(self) -> bool {
        self.0 & Self::GENERAL_HARDWARE_FAULT != 0
    }

    /// Sets or clears `general_hardware_fault` (bit 0).
    pub fn set_general_hardware_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::GENERAL_HARDWARE_FAULT;
        } else {
            self.0 &= !Self::GENERAL_HARDWARE_FAULT;
        }
    }

    /// System firmware has detected a serious, unexpected or abnormal condition. (bit 1)
    pub const fn general_firmware_fault(self) -> bool {
        self.0 & Self::GENERAL_FIRMWARE_FAULT != 0
    }

    /// Sets or clears `general_firmware_fault` (bit 1).
    pub fn set_general_firmware_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::GENERAL_FIRMWARE_FAULT;
        } else {
            self.0 &= !Self::GENERAL_FIRMWARE_FAULT;
        }
    }

    /// The system cannot keep up with the processing demand. (bit 2)
    pub const fn timing_overload(self) -> bool {
        self.0 & Self::TIMING_OVERLOAD != 0
    }

    /// Sets or clears `timing_overload` (bit 2).
    pub fn set_timing_overload(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIMING_OVERLOAD;
        } else {
            self.0 &= !Self::TIMING_OVERLOAD;
        }
    }

    /// A data buffer has reached its capacity. (bit 3)
    pub const fn buffer_overrun(self) -> bool {
        self.0 & Self::BUFFER_OVERRUN != 0
    }

    /// Sets or clears `buffer_overrun` (bit 3).
    pub fn set_buffer_overrun(&mut self, v: bool) {
        if v {
            self.0 |= Self::BUFFER_OVERRUN;
        } else {
            self.0 &= !Self::BUFFER_OVERRUN;
        }
    }

    /// Reserved (system). Reserved. (bits 4..=7)
    pub const fn reserved_system(self) -> u32 {
        (self.0 & Self::RESERVED_SYSTEM) >> 4
    }

    /// Sets `reserved_system` (bits 4..=7); higher bits of `v` are ignored.
    pub fn set_reserved_system(&mut self, v: u32) {
        self.0 = (self.0 & !Self::RESERVED_SYSTEM) | ((v << 4) & Self::RESERVED_SYSTEM);
    }

    /// Reserved (comms). Reserved. (bits 8..=11)
    pub const fn reserved_comms(self) -> u32 {
        (self.0 & Self::RESERVED_COMMS) >> 8
    }

    /// Sets `reserved_comms` (bits 8..=11); higher bits of `v` are ignored.
    pub fn set_reserved_comms(&mut self, v: u32) {
        self.0 = (self.0 & !Self::RESERVED_COMMS) | ((v << 8) & Self::RESERVED_COMMS);
    }

    /// The accelerometer has been damaged or is inoperative. (bit 12)
    pub const fn accelerometer_fault(self) -> bool {
        self.0 & Self::ACCELEROMETER_FAULT != 0
    }

    /// Sets or clears `accelerometer_fault` (bit 12).
    pub fn set_accelerometer_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCELEROMETER_FAULT;
        } else {
            self.0 &= !Self::ACCELEROMETER_FAULT;
        }
    }

    /// The gyroscope has been damaged or is inoperative. (bit 13)
    pub const fn gyroscope_fault(self) -> bool {
        self.0 & Self::GYROSCOPE_FAULT != 0
    }

    /// Sets or clears `gyroscope_fault` (bit 13).
    pub fn set_gyroscope_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYROSCOPE_FAULT;
        } else {
            self.0 &= !Self::GYROSCOPE_FAULT;
        }
    }

    /// The magnetometer has been damaged or is inoperative. (bit 14)
    pub const fn magnetometer_fault(self) -> bool {
        self.0 & Self::MAGNETOMETER_FAULT != 0
    }

    /// Sets or clears `magnetometer_fault` (bit 14).
    pub fn set_magnetometer_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAGNETOMETER_FAULT;
        } else {
            self.0 &= !Self::MAGNETOMETER_FAULT;
        }
    }

    /// The pressure sensor has been damaged or is inoperative. (bit 15)
    pub const fn pressure_sensor_fault(self) -> bool {
        self.0 & Self::PRESSURE_SENSOR_FAULT != 0
    }

    /// Sets or clears `pressure_sensor_fault` (bit 15).
    pub fn set_pressure_sensor_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::PRESSURE_SENSOR_FAULT;
        } else {
            self.0 &= !Self::PRESSURE_SENSOR_FAULT;
        }
    }

    /// Reserved (IMU). Reserved. (bits 16..=17)
    pub const fn reserved_imu(self) -> u32 {
        (self.0 & Self::RESERVED_IMU) >> 16
    }

    /// Sets `reserved_imu` (bits 16..=17); higher bits of `v` are ignored.
    pub fn set_reserved_imu(&mut self, v: u32) {
        self.0 = (self.0 & !Self::RESERVED_IMU) | ((v << 16) & Self::RESERVED_IMU);
    }

    /// One or more IMU calibration tables are invalid. (bit 18)
    pub const fn calibration_error(self) -> bool {
        self.0 & Self::CALIBRATION_ERROR != 0
    }

    /// Sets or clears `calibration_error` (bit 18).
    pub fn set_calibration_error(&mut self, v: bool) {
        if v {
            self.0 |= Self::CALIBRATION_ERROR;
        } else {
            self.0 &= !Self::CALIBRATION_ERROR;
        }
    }

    /// A problem has been detected in the IMU subsystem. (bit 19)
    pub const fn general_imu_fault(self) -> bool {
        self.0 & Self::GENERAL_IMU_FAULT != 0
    }

    /// Sets or clears `general_imu_fault` (bit 19).
    pub fn set_general_imu_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::GENERAL_IMU_FAULT;
        } else {
            self.0 &= !Self::GENERAL_IMU_FAULT;
        }
    }

    /// Reserved (filter). Reserved. (bits 20..=21)
    pub const fn reserved_filter(self) -> u32 {
        (self.0 & Self::RESERVED_FILTER) >> 20
    }

    /// Sets `reserved_filter` (bits 20..=21); higher bits of `v` are ignored.
    pub fn set_reserved_filter(&mut self, v: u32) {
        self.0 = (self.0 & !Self::RESERVED_FILTER) | ((v << 20) & Self::RESERVED_FILTER);
    }

    /// The filter solution is invalid (NaN in the filter output). (bit 22)
    pub const fn filter_solution_fault(self) -> bool {
        self.0 & Self::FILTER_SOLUTION_FAULT != 0
    }

    /// Sets or clears `filter_solution_fault` (bit 22).
    pub fn set_filter_solution_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_SOLUTION_FAULT;
        } else {
            self.0 &= !Self::FILTER_SOLUTION_FAULT;
        }
    }

    /// A problem has been detected in the filter subsystem. (bit 23)
    pub const fn general_filter_fault(self) -> bool {
        self.0 & Self::GENERAL_FILTER_FAULT != 0
    }

    /// Sets or clears `general_filter_fault` (bit 23).
    pub fn set_general_filter_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::GENERAL_FILTER_FAULT;
        } else {
            self.0 &= !Self::GENERAL_FILTER_FAULT;
        }
    }

    /// Reserved. Reserved. (bits 24..=31)
    pub const fn reserved(self) -> u32 {
        (self.0 & Self::RESERVED) >> 24
    }

    /// Sets `reserved` (bits 24..=31); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u32) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 24) & Self::RESERVED);
    }
}

impl crate::wire::Wire for Cv7BitFlags {
    const ZERO: Self = Self(0);
    const FIXED_SIZE: Option<usize> = <u32 as crate::wire::Wire>::FIXED_SIZE;

    #[inline(always)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        <u32 as crate::wire::Wire>::decode(r).map(Self)
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        self.0.encode(w)
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        self.0.write_json(w)
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Cv7BitFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u32 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// 3DM-CV7 continuous built-in test result (128 bits). The 16-byte continuous BIT bit map, one member per byte in wire order. Bit n of the map is bit (n mod 8) of byte n div 8 ("Relative Index (Byte.Bit)"). Bytes 0-3 are system bits, 4-7 IMU bits, 8-11 navigation filter bits and 12-15 GNSS bits. The bits latch until the message is sent; all unspecified bits are reserved and must be ignored.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cv7ContinuousBit {
    /// Bits 0-7: system.
    pub system_byte_0: crate::types::Cv7ContinuousBitSystem0,
    /// Bits 8-15: reserved (0.7-1.7).
    pub reserved_byte_1: u8,
    /// Bits 16-23: IMU and filter process faults.
    pub system_byte_2: crate::types::Cv7ContinuousBitSystem2,
    /// Bits 24-31: GNSS process faults.
    pub system_byte_3: crate::types::Cv7ContinuousBitSystem3,
    /// Bits 32-39: IMU communication, timing, calibration.
    pub imu_byte_4: crate::types::Cv7ContinuousBitImu4,
    /// Bits 40-47: accelerometer and gyroscope.
    pub imu_byte_5: crate::types::Cv7ContinuousBitImu5,
    /// Bits 48-55: magnetometer and pressure sensor.
    pub imu_byte_6: crate::types::Cv7ContinuousBitImu6,
    /// Bits 56-63: factory bits.
    pub imu_byte_7: crate::types::Cv7ContinuousBitImu7,
    /// Bits 64-71: filter timing.
    pub nav_byte_8: crate::types::Cv7ContinuousBitNav8,
    /// Bits 72-79: reserved.
    pub reserved_byte_9: u8,
    /// Bits 80-87: reserved.
    pub reserved_byte_10: u8,
    /// Bits 88-95: reserved.
    pub reserved_byte_11: u8,
    /// Bits 96-103: reserved.
    pub reserved_byte_12: u8,
    /// Bits 104-111: GNSS receivers.
    pub gnss_byte_13: crate::types::Cv7ContinuousBitGnss13,
    /// Bits 112-119: GNSS receivers.
    pub gnss_byte_14: crate::types::Cv7ContinuousBitGnss14,
    /// Bits 120-127: reserved.
    pub reserved_byte_15: u8,
}

impl Default for Cv7ContinuousBit {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Cv7ContinuousBit {
    const ZERO: Self = Self {
        system_byte_0: <crate::types::Cv7ContinuousBitSystem0 as crate::wire::Wire>::ZERO,
        reserved_byte_1: <u8 as crate::wire::Wire>::ZERO,
        system_byte_2: <crate::types::Cv7ContinuousBitSystem2 as crate::wire::Wire>::ZERO,
        system_byte_3: <crate::types::Cv7ContinuousBitSystem3 as crate::wire::Wire>::ZERO,
        imu_byte_4: <crate::types::Cv7ContinuousBitImu4 as crate::wire::Wire>::ZERO,
        imu_byte_5: <crate::types::Cv7ContinuousBitImu5 as crate::wire::Wire>::ZERO,
        imu_byte_6: <crate::types::Cv7ContinuousBitImu6 as crate::wire::Wire>::ZERO,
        imu_byte_7: <crate::types::Cv7ContinuousBitImu7 as crate::wire::Wire>::ZERO,
        nav_byte_8: <crate::types::Cv7ContinuousBitNav8 as crate::wire::Wire>::ZERO,
        reserved_byte_9: <u8 as crate::wire::Wire>::ZERO,
        reserved_byte_10: <u8 as crate::wire::Wire>::ZERO,
        reserved_byte_11: <u8 as crate::wire::Wire>::ZERO,
        reserved_byte_12: <u8 as crate::wire::Wire>::ZERO,
        gnss_byte_13: <crate::types::Cv7ContinuousBitGnss13 as crate::wire::Wire>::ZERO,
        gnss_byte_14: <crate::types::Cv7ContinuousBitGnss14 as crate::wire::Wire>::ZERO,
        reserved_byte_15: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_system_byte_0 =
            <crate::types::Cv7ContinuousBitSystem0 as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("system_byte_0"))?;
        let p_reserved_byte_1 =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved_byte_1"))?;
        let p_system_byte_2 =
            <crate::types::Cv7ContinuousBitSystem2 as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("system_byte_2"))?;
        let p_system_byte_3 =
            <crate::types::Cv7ContinuousBitSystem3 as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("system_byte_3"))?;
        let p_imu_byte_4 = <crate::types::Cv7ContinuousBitImu4 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("imu_byte_4"))?;
        let p_imu_byte_5 = <crate::types::Cv7ContinuousBitImu5 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("imu_byte_5"))?;
        let p_imu_byte_6 = <crate::types::Cv7ContinuousBitImu6 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("imu_byte_6"))?;
        let p_imu_byte_7 = <crate::types::Cv7ContinuousBitImu7 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("imu_byte_7"))?;
        let p_nav_byte_8 = <crate::types::Cv7ContinuousBitNav8 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("nav_byte_8"))?;
        let p_reserved_byte_9 =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved_byte_9"))?;
        let p_reserved_byte_10 =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved_byte_10"))?;
        let p_reserved_byte_11 =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved_byte_11"))?;
        let p_reserved_byte_12 =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved_byte_12"))?;
        let p_gnss_byte_13 = <crate::types::Cv7ContinuousBitGnss13 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("gnss_byte_13"))?;
        let p_gnss_byte_14 = <crate::types::Cv7ContinuousBitGnss14 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("gnss_byte_14"))?;
        let p_reserved_byte_15 =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved_byte_15"))?;
        Ok(Self {
            system_byte_0: p_system_byte_0,
            reserved_byte_1: p_reserved_byte_1,
            system_byte_2: p_system_byte_2,
            system_byte_3: p_system_byte_3,
            imu_byte_4: p_imu_byte_4,
            imu_byte_5: p_imu_byte_5,
            imu_byte_6: p_imu_byte_6,
            imu_byte_7: p_imu_byte_7,
            nav_byte_8: p_nav_byte_8,
            reserved_byte_9: p_reserved_byte_9,
            reserved_byte_10: p_reserved_byte_10,
            reserved_byte_11: p_reserved_byte_11,
            reserved_byte_12: p_reserved_byte_12,
            gnss_byte_13: p_gnss_byte_13,
            gnss_byte_14: p_gnss_byte_14,
            reserved_byte_15: p_reserved_byte_15,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.system_byte_0;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("system_byte_0"))?;
        let v = &self.reserved_byte_1;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved_byte_1"))?;
        let v = &self.system_byte_2;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("system_byte_2"))?;
        let v = &self.system_byte_3;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("system_byte_3"))?;
        let v = &self.imu_byte_4;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_byte_4"))?;
        let v = &self.imu_byte_5;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_byte_5"))?;
        let v = &self.imu_byte_6;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_byte_6"))?;
        let v = &self.imu_byte_7;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_byte_7"))?;
        let v = &self.nav_byte_8;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("nav_byte_8"))?;
        let v = &self.reserved_byte_9;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved_byte_9"))?;
        let v = &self.reserved_byte_10;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved_byte_10"))?;
        let v = &self.reserved_byte_11;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved_byte_11"))?;
        let v = &self.reserved_byte_12;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved_byte_12"))?;
        let v = &self.gnss_byte_13;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_byte_13"))?;
        let v = &self.gnss_byte_14;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_byte_14"))?;
        let v = &self.reserved_byte_15;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved_byte_15"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.system_byte_0;
        crate::json::key(w, &mut first, "system_byte_0")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved_byte_1;
        crate::json::key(w, &mut first, "reserved_byte_1")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.system_byte_2;
        crate::json::key(w, &mut first, "system_byte_2")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.system_byte_3;
        crate::json::key(w, &mut first, "system_byte_3")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_byte_4;
        crate::json::key(w, &mut first, "imu_byte_4")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_byte_5;
        crate::json::key(w, &mut first, "imu_byte_5")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_byte_6;
        crate::json::key(w, &mut first, "imu_byte_6")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_byte_7;
        crate::json::key(w, &mut first, "imu_byte_7")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.nav_byte_8;
        crate::json::key(w, &mut first, "nav_byte_8")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved_byte_9;
        crate::json::key(w, &mut first, "reserved_byte_9")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved_byte_10;
        crate::json::key(w, &mut first, "reserved_byte_10")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved_byte_11;
        crate::json::key(w, &mut first, "reserved_byte_11")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved_byte_12;
        crate::json::key(w, &mut first, "reserved_byte_12")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_byte_13;
        crate::json::key(w, &mut first, "gnss_byte_13")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_byte_14;
        crate::json::key(w, &mut first, "gnss_byte_14")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved_byte_15;
        crate::json::key(w, &mut first, "reserved_byte_15")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Cv7ContinuousBit {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "system_byte_0",
                "reserved_byte_1",
                "system_byte_2",
                "system_byte_3",
                "imu_byte_4",
                "imu_byte_5",
                "imu_byte_6",
                "imu_byte_7",
                "nav_byte_8",
                "reserved_byte_9",
                "reserved_byte_10",
                "reserved_byte_11",
                "reserved_byte_12",
                "gnss_byte_13",
                "gnss_byte_14",
                "reserved_byte_15",
            ],
        )?;
        let p_system_byte_0 = o.req(
            "system_byte_0",
            <crate::types::Cv7ContinuousBitSystem0 as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved_byte_1 = o.req(
            "reserved_byte_1",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_system_byte_2 = o.req(
            "system_byte_2",
            <crate::types::Cv7ContinuousBitSystem2 as crate::json_read::FromJson>::from_json,
        )?;
        let p_system_byte_3 = o.req(
            "system_byte_3",
            <crate::types::Cv7ContinuousBitSystem3 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_byte_4 = o.req(
            "imu_byte_4",
            <crate::types::Cv7ContinuousBitImu4 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_byte_5 = o.req(
            "imu_byte_5",
            <crate::types::Cv7ContinuousBitImu5 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_byte_6 = o.req(
            "imu_byte_6",
            <crate::types::Cv7ContinuousBitImu6 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_byte_7 = o.req(
            "imu_byte_7",
            <crate::types::Cv7ContinuousBitImu7 as crate::json_read::FromJson>::from_json,
        )?;
        let p_nav_byte_8 = o.req(
            "nav_byte_8",
            <crate::types::Cv7ContinuousBitNav8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved_byte_9 = o.req(
            "reserved_byte_9",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved_byte_10 = o.req(
            "reserved_byte_10",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved_byte_11 = o.req(
            "reserved_byte_11",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved_byte_12 = o.req(
            "reserved_byte_12",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_byte_13 = o.req(
            "gnss_byte_13",
            <crate::types::Cv7ContinuousBitGnss13 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_byte_14 = o.req(
            "gnss_byte_14",
            <crate::types::Cv7ContinuousBitGnss14 as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved_byte_15 = o.req(
            "reserved_byte_15",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            system_byte_0: p_system_byte_0,
            reserved_byte_1: p_reserved_byte_1,
            system_byte_2: p_system_byte_2,
            system_byte_3: p_system_byte_3,
            imu_byte_4: p_imu_byte_4,
            imu_byte_5: p_imu_byte_5,
            imu_byte_6: p_imu_byte_6,
            imu_byte_7: p_imu_byte_7,
            nav_byte_8: p_nav_byte_8,
            reserved_byte_9: p_reserved_byte_9,
            reserved_byte_10: p_reserved_byte_10,
            reserved_byte_11: p_reserved_byte_11,
            reserved_byte_12: p_reserved_byte_12,
            gnss_byte_13: p_gnss_byte_13,
            gnss_byte_14: p_gnss_byte_14,
            reserved_byte_15: p_reserved_byte_15,
        })
    }
}

/// Continuous BIT byte 13: GNSS receivers (bits 104-111).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitGnss13(pub u8);

impl Cv7ContinuousBitGnss13 {
    /// Mask of `reserved_104` (bit 0).
    pub const RESERVED_104: u8 = 0x01;
    /// Mask of `receiver_1_fault` (bit 1).
    pub const RECEIVER_1_FAULT: u8 = 0x02;
    /// Mask of `reserved_106_107` (bits 2..=3).
    pub const RESERVED_106_107: u8 = 0x0C;
    /// Mask of `receiver_1_no_solution` (bit 4).
    pub const RECEIVER_1_NO_SOLUTION: u8 = 0x10;
    /// Mask of `reserved_109` (bit 5).
    pub const RESERVED_109: u8 = 0x20;
    /// Mask of `receiver_2_fault` (bit 6).
    pub const RECEIVER_2_FAULT: u8 = 0x40;
    /// Mask of `reserved_111` (bit 7).
    pub const RESERVED_111: u8 = 0x80;

    /// Bit 104 (13.0): GNSS reserved. Reserved. (bit 0)
    pub const fn reserved_104(self) -> bool {
        self.0 & Self::RESERVED_104 != 0
    }

    /// Sets or clears `reserved_104` (bit 0).
    pub fn set_reserved_104(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_104;
        } else {
            self.0 &= !Self::RESERVED_104;
        }
    }

    /// Bit 105 (13.1): no communication with internal GNSS receiver 1. (bit 1)
    pub const fn receiver_1_fault(self) -> bool {
        self.0 & Self::RECEIVER_1_FAULT != 0
    }

    /// Sets or clears `receiver_1_fault` (bit 1).
    pub fn set_receiver_1_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::RECEIVER_1_FAULT;
        } else {
            self.0 &= !Self::RECEIVER_1_FAULT;
        }
    }

    /// Bits 106-107 (13.2-13.3): GNSS reserved. Reserved. (bits 2..=3)
    pub const fn reserved_106_107(self) -> u8 {
        (self.0 & Self::RESERVED_106_107) >> 2
    }

    /// Sets `reserved_106_107` (bits 2..=3); higher bits of `v` are ignored.
    pub fn set_reserved_106_107(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED_106_107) | ((v << 2) & Self::RESERVED_106_107);
    }

    /// Bit 108 (13.4): internal receiver 1 has no valid solution (check antenna and sky view). (bit 4)
    pub const fn receiver_1_no_solution(self) -> bool {
        self.0 & Self::RECEIVER_1_NO_SOLUTION != 0
    }

    /// Sets or clears `receiver_1_no_solution` (bit 4).
    pub fn set_receiver_1_no_solution(&mut self, v: bool) {
        if v {
            self.0 |= Self::RECEIVER_1_NO_SOLUTION;
        } else {
            self.0 &= !Self::RECEIVER_1_NO_SOLUTION;
        }
    }

    /// Bit 109 (13.5): GNSS reserved. Reserved. (bit 5)
    pub const fn reserved_109(self) -> bool {
        self.0 & Self::RESERVED_109 != 0
    }

    /// Sets or clears `reserved_109` (bit 5).
    pub fn set_reserved_109(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_109;
        } else {
            self.0 &= !Self::RESERVED_109;
        }
    }

    /// Bit 110 (13.6): no communication with internal GNSS receiver 2. (bit 6)
    pub const fn receiver_2_fault(self) -> bool {
        self.0 & Self::RECEIVER_2_FAULT != 0
    }

    /// Sets or clears `receiver_2_fault` (bit 6).
    pub fn set_receiver_2_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::RECEIVER_2_FAULT;
        } else {
            self.0 &= !Self::RECEIVER_2_FAULT;
        }
    }

    /// Bit 111 (13.7): GNSS reserved. Reserved. (bit 7)
    pub const fn reserved_111(self) -> bool {
        self.0 & Self::RESERVED_111 != 0
    }

    /// Sets or clears `reserved_111` (bit 7).
    pub fn set_reserved_111(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_111;
        } else {
            self.0 &= !Self::RESERVED_111;
        }
    }
}

impl crate::wire::Wire for Cv7ContinuousBitGnss13 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitGnss13 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 14: GNSS receivers (bits 112-119).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitGnss14(pub u8);

impl Cv7ContinuousBitGnss14 {
    /// Mask of `reserved_112` (bit 0).
    pub const RESERVED_112: u8 = 0x01;
    /// Mask of `receiver_2_no_solution` (bit 1).
    pub const RECEIVER_2_NO_SOLUTION: u8 = 0x02;
    /// Mask of `reserved_114_119` (bits 2..=7).
    pub const RESERVED_114_119: u8 = 0xFC;

    /// Bit 112 (14.0): GNSS reserved. Reserved. (bit 0)
    pub const fn reserved_112(self) -> bool {
        self.0 & Self::RESERVED_112 != 0
    }

    /// Sets or clears `reserved_112` (bit 0).
    pub fn set_reserved_112(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_112;
        } else {
            self.0 &= !Self::RESERVED_112;
        }
    }

    /// Bit 113 (14.1): internal receiver 2 has no valid solution (check antenna and sky view). (bit 1)
    pub const fn receiver_2_no_solution(self) -> bool {
        self.0 & Self::RECEIVER_2_NO_SOLUTION != 0
    }

    /// Sets or clears `receiver_2_no_solution` (bit 1).
    pub fn set_receiver_2_no_solution(&mut self, v: bool) {
        if v {
            self.0 |= Self::RECEIVER_2_NO_SOLUTION;
        } else {
            self.0 &= !Self::RECEIVER_2_NO_SOLUTION;
        }
    }

    /// Bits 114-119 (14.2-14.7): GNSS reserved. Reserved. (bits 2..=7)
    pub const fn reserved_114_119(self) -> u8 {
        (self.0 & Self::RESERVED_114_119) >> 2
    }

    /// Sets `reserved_114_119` (bits 2..=7); higher bits of `v` are ignored.
    pub fn set_reserved_114_119(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED_114_119) | ((v << 2) & Self::RESERVED_114_119);
    }
}

impl crate::wire::Wire for Cv7ContinuousBitGnss14 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitGnss14 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 4: IMU (bits 32-39).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitImu4(pub u8);

impl Cv7ContinuousBitImu4 {
    /// Mask of `reserved_32` (bit 0).
    pub const RESERVED_32: u8 = 0x01;
    /// Mask of `imu_communication_fault` (bit 1).
    pub const IMU_COMMUNICATION_FAULT: u8 = 0x02;
    /// Mask of `imu_timing_overrun` (bit 2).
    pub const IMU_TIMING_OVERRUN: u8 = 0x04;
    /// Mask of `reserved_35` (bit 3).
    pub const RESERVED_35: u8 = 0x08;
    /// Mask of `imu_calibration_error_accelerometer` (bit 4).
    pub const IMU_CALIBRATION_ERROR_ACCELEROMETER: u8 = 0x10;
    /// Mask of `imu_calibration_error_gyroscope` (bit 5).
    pub const IMU_CALIBRATION_ERROR_GYROSCOPE: u8 = 0x20;
    /// Mask of `imu_calibration_error_magnetometer` (bit 6).
    pub const IMU_CALIBRATION_ERROR_MAGNETOMETER: u8 = 0x40;
    /// Mask of `reserved_39` (bit 7).
    pub const RESERVED_39: u8 = 0x80;

    /// Bit 32 (4.0): IMU reserved. Reserved. (bit 0)
    pub const fn reserved_32(self) -> bool {
        self.0 & Self::RESERVED_32 != 0
    }

    /// Sets or clears `reserved_32` (bit 0).
    pub fn set_reserved_32(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_32;
        } else {
            self.0 &= !Self::RESERVED_32;
        }
    }

    /// Bit 33 (4.1): no communication with the IMU. (bit 1)
    pub const fn imu_communication_fault(self) -> bool {
        self.0 & Self::IMU_COMMUNICATION_FAULT != 0
    }

    /// Sets or clears `imu_communication_fault` (bit 1).
    pub fn set_imu_communication_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_COMMUNICATION_FAULT;
        } else {
            self.0 &= !Self::IMU_COMMUNICATION_FAULT;
        }
    }

    /// Bit 34 (4.2): IMU core processes take longer than their allotted time. (bit 2)
    pub const fn imu_timing_overrun(self) -> bool {
        self.0 & Self::IMU_TIMING_OVERRUN != 0
    }

    /// Sets or clears `imu_timing_overrun` (bit 2).
    pub fn set_imu_timing_overrun(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_TIMING_OVERRUN;
        } else {
            self.0 &= !Self::IMU_TIMING_OVERRUN;
        }
    }

    /// Bit 35 (4.3): IMU reserved. Reserved. (bit 3)
    pub const fn reserved_35(self) -> bool {
        self.0 & Self::RESERVED_35 != 0
    }

    /// Sets or clears `reserved_35` (bit 3).
    pub fn set_reserved_35(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_35;
        } else {
            self.0 &= !Self::RESERVED_35;
        }
    }

    /// Bit 36 (4.4): problem with the accelerometer calibration. (bit 4)
    pub const fn imu_calibration_error_accelerometer(self) -> bool {
        self.0 & Self::IMU_CALIBRATION_ERROR_ACCELEROMETER != 0
    }

    /// Sets or clears `imu_calibration_error_accelerometer` (bit 4).
    pub fn set_imu_calibration_error_accelerometer(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_CALIBRATION_ERROR_ACCELEROMETER;
        } else {
            self.0 &= !Self::IMU_CALIBRATION_ERROR_ACCELEROMETER;
        }
    }

    /// Bit 37 (4.5): problem with the gyroscope calibration. (bit 5)
    pub const fn imu_calibration_error_gyroscope(self) -> bool {
        self.0 & Self::IMU_CALIBRATION_ERROR_GYROSCOPE != 0
    }

    /// Sets or clears `imu_calibration_error_gyroscope` (bit 5).
    pub fn set_imu_calibration_error_gyroscope(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_CALIBRATION_ERROR_GYROSCOPE;
        } else {
            self.0 &= !Self::IMU_CALIBRATION_ERROR_GYROSCOPE;
        }
    }

    /// Bit 38 (4.6): problem with the magnetometer calibration. (bit 6)
    pub const fn imu_calibration_error_magnetometer(self) -> bool {
        self.0 & Self::IMU_CALIBRATION_ERROR_MAGNETOMETER != 0
    }

    /// Sets or clears `imu_calibration_error_magnetometer` (bit 6).
    pub fn set_imu_calibration_error_magnetometer(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_CALIBRATION_ERROR_MAGNETOMETER;
        } else {
            self.0 &= !Self::IMU_CALIBRATION_ERROR_MAGNETOMETER;
        }
    }

    /// Bit 39 (4.7): IMU calibration error, reserved. Reserved. (bit 7)
    pub const fn reserved_39(self) -> bool {
        self.0 & Self::RESERVED_39 != 0
    }

    /// Sets or clears `reserved_39` (bit 7).
    pub fn set_reserved_39(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_39;
        } else {
            self.0 &= !Self::RESERVED_39;
        }
    }
}

impl crate::wire::Wire for Cv7ContinuousBitImu4 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitImu4 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 5: IMU accelerometer and gyroscope (bits 40-47).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitImu5(pub u8);

impl Cv7ContinuousBitImu5 {
    /// Mask of `accelerometer_general_fault` (bit 0).
    pub const ACCELEROMETER_GENERAL_FAULT: u8 = 0x01;
    /// Mask of `accelerometer_overrange` (bit 1).
    pub const ACCELEROMETER_OVERRANGE: u8 = 0x02;
    /// Mask of `accelerometer_self_test_fail` (bit 2).
    pub const ACCELEROMETER_SELF_TEST_FAIL: u8 = 0x04;
    /// Mask of `reserved_43` (bit 3).
    pub const RESERVED_43: u8 = 0x08;
    /// Mask of `gyroscope_general_fault` (bit 4).
    pub const GYROSCOPE_GENERAL_FAULT: u8 = 0x10;
    /// Mask of `gyroscope_overrange` (bit 5).
    pub const GYROSCOPE_OVERRANGE: u8 = 0x20;
    /// Mask of `gyroscope_self_test_fail` (bit 6).
    pub const GYROSCOPE_SELF_TEST_FAIL: u8 = 0x40;
    /// Mask of `reserved_47` (bit 7).
    pub const RESERVED_47: u8 = 0x80;

    /// Bit 40 (5.0): the accelerometer will not initialize. (bit 0)
    pub const fn accelerometer_general_fault(self) -> bool {
        self.0 & Self::ACCELEROMETER_GENERAL_FAULT != 0
    }

    /// Sets or clears `accelerometer_general_fault` (bit 0).
    pub fn set_accelerometer_general_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCELEROMETER_GENERAL_FAULT;
        } else {
            self.0 &= !Self::ACCELEROMETER_GENERAL_FAULT;
        }
    }

    /// Bit 41 (5.1): one or more axes near or beyond the selected range. (bit 1)
    pub const fn accelerometer_overrange(self) -> bool {
        self.0 & Self::ACCELEROMETER_OVERRANGE != 0
    }

    /// Sets or clears `accelerometer_overrange` (bit 1).
    pub fn set_accelerometer_overrange(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCELEROMETER_OVERRANGE;
        } else {
            self.0 &= !Self::ACCELEROMETER_OVERRANGE;
        }
    }

    /// Bit 42 (5.2): accelerometer self-test failed (updated by the commanded BIT only). (bit 2)
    pub const fn accelerometer_self_test_fail(self) -> bool {
        self.0 & Self::ACCELEROMETER_SELF_TEST_FAIL != 0
    }

    /// Sets or clears `accelerometer_self_test_fail` (bit 2).
    pub fn set_accelerometer_self_test_fail(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCELEROMETER_SELF_TEST_FAIL;
        } else {
            self.0 &= !Self::ACCELEROMETER_SELF_TEST_FAIL;
        }
    }

    /// Bit 43 (5.3): accelerometer reserved. Reserved. (bit 3)
    pub const fn reserved_43(self) -> bool {
        self.0 & Self::RESERVED_43 != 0
    }

    /// Sets or clears `reserved_43` (bit 3).
    pub fn set_reserved_43(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_43;
        } else {
            self.0 &= !Self::RESERVED_43;
        }
    }

    /// Bit 44 (5.4): the gyroscope will not initialize. (bit 4)
    pub const fn gyroscope_general_fault(self) -> bool {
        self.0 & Self::GYROSCOPE_GENERAL_FAULT != 0
    }

    /// Sets or clears `gyroscope_general_fault` (bit 4).
    pub fn set_gyroscope_general_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYROSCOPE_GENERAL_FAULT;
        } else {
            self.0 &= !Self::GYROSCOPE_GENERAL_FAULT;
        }
    }

    /// Bit 45 (5.5): one or more axes near or beyond the selected range. (bit 5)
    pub const fn gyroscope_overrange(self) -> bool {
        self.0 & Self::GYROSCOPE_OVERRANGE != 0
    }

    /// Sets or clears `gyroscope_overrange` (bit 5).
    pub fn set_gyroscope_overrange(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYROSCOPE_OVERRANGE;
        } else {
            self.0 &= !Self::GYROSCOPE_OVERRANGE;
        }
    }

    /// Bit 46 (5.6): gyroscope self-test failed (updated by the commanded BIT only). (bit 6)
    pub const fn gyroscope_self_test_fail(self) -> bool {
        self.0 & Self::GYROSCOPE_SELF_TEST_FAIL != 0
    }

    /// Sets or clears `gyroscope_self_test_fail` (bit 6).
    pub fn set_gyroscope_self_test_fail(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYROSCOPE_SELF_TEST_FAIL;
        } else {
            self.0 &= !Self::GYROSCOPE_SELF_TEST_FAIL;
        }
    }

    /// Bit 47 (5.7): gyroscope reserved. Reserved. (bit 7)
    pub const fn reserved_47(self) -> bool {
        self.0 & Self::RESERVED_47 != 0
    }

    /// Sets or clears `reserved_47` (bit 7).
    pub fn set_reserved_47(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_47;
        } else {
            self.0 &= !Self::RESERVED_47;
        }
    }
}

impl crate::wire::Wire for Cv7ContinuousBitImu5 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitImu5 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 6: IMU magnetometer and pressure sensor (bits 48-55).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitImu6(pub u8);

impl Cv7ContinuousBitImu6 {
    /// Mask of `magnetometer_general_fault` (bit 0).
    pub const MAGNETOMETER_GENERAL_FAULT: u8 = 0x01;
    /// Mask of `magnetometer_overrange` (bit 1).
    pub const MAGNETOMETER_OVERRANGE: u8 = 0x02;
    /// Mask of `magnetometer_self_test_fail` (bit 2).
    pub const MAGNETOMETER_SELF_TEST_FAIL: u8 = 0x04;
    /// Mask of `reserved_51` (bit 3).
    pub const RESERVED_51: u8 = 0x08;
    /// Mask of `pressure_sensor_general_fault` (bit 4).
    pub const PRESSURE_SENSOR_GENERAL_FAULT: u8 = 0x10;
    /// Mask of `pressure_sensor_overrange` (bit 5).
    pub const PRESSURE_SENSOR_OVERRANGE: u8 = 0x20;
    /// Mask of `pressure_sensor_self_test_fail` (bit 6).
    pub const PRESSURE_SENSOR_SELF_TEST_FAIL: u8 = 0x40;
    /// Mask of `reserved_55` (bit 7).
    pub const RESERVED_55: u8 = 0x80;

    /// Bit 48 (6.0): the magnetometer will not initialize. (bit 0)
    pub const fn magnetometer_general_fault(self) -> bool {
        self.0 & Self::MAGNETOMETER_GENERAL_FAULT != 0
    }

    /// Sets or clears `magnetometer_general_fault` (bit 0).
    pub fn set_magnetometer_general_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAGNETOMETER_GENERAL_FAULT;
        } else {
            self.0 &= !Self::MAGNETOMETER_GENERAL_FAULT;
        }
    }

    /// Bit 49 (6.1): one or more axes near or beyond the supported range. (bit 1)
    pub const fn magnetometer_overrange(self) -> bool {
        self.0 & Self::MAGNETOMETER_OVERRANGE != 0
    }

    /// Sets or clears `magnetometer_overrange` (bit 1).
    pub fn set_magnetometer_overrange(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAGNETOMETER_OVERRANGE;
        } else {
            self.0 &= !Self::MAGNETOMETER_OVERRANGE;
        }
    }

    /// Bit 50 (6.2): magnetometer self-test failed (updated by the commanded BIT only). (bit 2)
    pub const fn magnetometer_self_test_fail(self) -> bool {
        self.0 & Self::MAGNETOMETER_SELF_TEST_FAIL != 0
    }

    /// Sets or clears `magnetometer_self_test_fail` (bit 2).
    pub fn set_magnetometer_self_test_fail(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAGNETOMETER_SELF_TEST_FAIL;
        } else {
            self.0 &= !Self::MAGNETOMETER_SELF_TEST_FAIL;
        }
    }

    /// Bit 51 (6.3): magnetometer reserved. Reserved. (bit 3)
    pub const fn reserved_51(self) -> bool {
        self.0 & Self::RESERVED_51 != 0
    }

    /// Sets or clears `reserved_51` (bit 3).
    pub fn set_reserved_51(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_51;
        } else {
            self.0 &= !Self::RESERVED_51;
        }
    }

    /// Bit 52 (6.4): the pressure sensor will not initialize. (bit 4)
    pub const fn pressure_sensor_general_fault(self) -> bool {
        self.0 & Self::PRESSURE_SENSOR_GENERAL_FAULT != 0
    }

    /// Sets or clears `pressure_sensor_general_fault` (bit 4).
    pub fn set_pressure_sensor_general_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::PRESSURE_SENSOR_GENERAL_FAULT;
        } else {
            self.0 &= !Self::PRESSURE_SENSOR_GENERAL_FAULT;
        }
    }

    /// Bit 53 (6.5): pressure outside the supported range. (bit 5)
    pub const fn pressure_sensor_overrange(self) -> bool {
        self.0 & Self::PRESSURE_SENSOR_OVERRANGE != 0
    }

    /// Sets or clears `pressure_sensor_overrange` (bit 5).
    pub fn set_pressure_sensor_overrange(&mut self, v: bool) {
        if v {
            self.0 |= Self::PRESSURE_SENSOR_OVERRANGE;
        } else {
            self.0 &= !Self::PRESSURE_SENSOR_OVERRANGE;
        }
    }

    /// Bit 54 (6.6): pressure sensor self-test failed (updated by the commanded BIT only). (bit 6)
    pub const fn pressure_sensor_self_test_fail(self) -> bool {
        self.0 & Self::PRESSURE_SENSOR_SELF_TEST_FAIL != 0
    }

    /// Sets or clears `pressure_sensor_self_test_fail` (bit 6).
    pub fn set_pressure_sensor_self_test_fail(&mut self, v: bool) {
        if v {
            self.0 |= Self::PRESSURE_SENSOR_SELF_TEST_FAIL;
        } else {
            self.0 &= !Self::PRESSURE_SENSOR_SELF_TEST_FAIL;
        }
    }

    /// Bit 55 (6.7): pressure sensor reserved. Reserved. (bit 7)
    pub const fn reserved_55(self) -> bool {
        self.0 & Self::RESERVED_55 != 0
    }

    /// Sets or clears `reserved_55` (bit 7).
    pub fn set_reserved_55(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_55;
        } else {
            self.0 &= !Self::RESERVED_55;
        }
    }
}

impl crate::wire::Wire for Cv7ContinuousBitImu6 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitImu6 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 7: IMU (bits 56-63).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitImu7(pub u8);

impl Cv7ContinuousBitImu7 {
    /// Mask of `factory_bits_invalid` (bit 0).
    pub const FACTORY_BITS_INVALID: u8 = 0x01;
    /// Mask of `reserved_57_63` (bits 1..=7).
    pub const RESERVED_57_63: u8 = 0xFE;

    /// Bit 56 (7.0): the device has lost its configuration; contact support. (bit 0)
    pub const fn factory_bits_invalid(self) -> bool {
        self.0 & Self::FACTORY_BITS_INVALID != 0
    }

    /// Sets or clears `factory_bits_invalid` (bit 0).
    pub fn set_factory_bits_invalid(&mut self, v: bool) {
        if v {
            self.0 |= Self::FACTORY_BITS_INVALID;
        } else {
            self.0 &= !Self::FACTORY_BITS_INVALID;
        }
    }

    /// Bits 57-63 (7.1-7.7): reserved. Reserved. (bits 1..=7)
    pub const fn reserved_57_63(self) -> u8 {
        (self.0 & Self::RESERVED_57_63) >> 1
    }

    /// Sets `reserved_57_63` (bits 1..=7); higher bits of `v` are ignored.
    pub fn set_reserved_57_63(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED_57_63) | ((v << 1) & Self::RESERVED_57_63);
    }
}

impl crate::wire::Wire for Cv7ContinuousBitImu7 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitImu7 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 8: navigation filter (bits 64-71).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitNav8(pub u8);

impl Cv7ContinuousBitNav8 {
    /// Mask of `reserved_64` (bit 0).
    pub const RESERVED_64: u8 = 0x01;
    /// Mask of `reserved_65` (bit 1).
    pub const RESERVED_65: u8 = 0x02;
    /// Mask of `filter_timing_overrun` (bit 2).
    pub const FILTER_TIMING_OVERRUN: u8 = 0x04;
    /// Mask of `filter_timing_underrun` (bit 3).
    pub const FILTER_TIMING_UNDERRUN: u8 = 0x08;
    /// Mask of `reserved_68_71` (bits 4..=7).
    pub const RESERVED_68_71: u8 = 0xF0;

    /// Bit 64 (8.0): reserved. Reserved. (bit 0)
    pub const fn reserved_64(self) -> bool {
        self.0 & Self::RESERVED_64 != 0
    }

    /// Sets or clears `reserved_64` (bit 0).
    pub fn set_reserved_64(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_64;
        } else {
            self.0 &= !Self::RESERVED_64;
        }
    }

    /// Bit 65 (8.1): reserved. Reserved. (bit 1)
    pub const fn reserved_65(self) -> bool {
        self.0 & Self::RESERVED_65 != 0
    }

    /// Sets or clears `reserved_65` (bit 1).
    pub fn set_reserved_65(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_65;
        } else {
            self.0 &= !Self::RESERVED_65;
        }
    }

    /// Bit 66 (8.2): filter processes take longer than their allotted time. (bit 2)
    pub const fn filter_timing_overrun(self) -> bool {
        self.0 & Self::FILTER_TIMING_OVERRUN != 0
    }

    /// Sets or clears `filter_timing_overrun` (bit 2).
    pub fn set_filter_timing_overrun(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_TIMING_OVERRUN;
        } else {
            self.0 &= !Self::FILTER_TIMING_OVERRUN;
        }
    }

    /// Bit 67 (8.3): filter processes are being skipped. (bit 3)
    pub const fn filter_timing_underrun(self) -> bool {
        self.0 & Self::FILTER_TIMING_UNDERRUN != 0
    }

    /// Sets or clears `filter_timing_underrun` (bit 3).
    pub fn set_filter_timing_underrun(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_TIMING_UNDERRUN;
        } else {
            self.0 &= !Self::FILTER_TIMING_UNDERRUN;
        }
    }

    /// Bits 68-71 (8.4-8.7): reserved (printed as GNSS reserved). Reserved. (bits 4..=7)
    pub const fn reserved_68_71(self) -> u8 {
        (self.0 & Self::RESERVED_68_71) >> 4
    }

    /// Sets `reserved_68_71` (bits 4..=7); higher bits of `v` are ignored.
    pub fn set_reserved_68_71(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED_68_71) | ((v << 4) & Self::RESERVED_68_71);
    }
}

impl crate::wire::Wire for Cv7ContinuousBitNav8 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitNav8 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 0: system (bits 0-7).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitSystem0(pub u8);

impl Cv7ContinuousBitSystem0 {
    /// Mask of `system_clock_failure` (bit 0).
    pub const SYSTEM_CLOCK_FAILURE: u8 = 0x01;
    /// Mask of `power_fault` (bit 1).
    pub const POWER_FAULT: u8 = 0x02;
    /// Mask of `reserved_2_3` (bits 2..=3).
    pub const RESERVED_2_3: u8 = 0x0C;
    /// Mask of `firmware_fault` (bit 4).
    pub const FIRMWARE_FAULT: u8 = 0x10;
    /// Mask of `timing_overload` (bit 5).
    pub const TIMING_OVERLOAD: u8 = 0x20;
    /// Mask of `buffer_overrun` (bit 6).
    pub const BUFFER_OVERRUN: u8 = 0x40;
    /// Mask of `reserved_7` (bit 7).
    pub const RESERVED_7: u8 = 0x80;

    /// Bit 0 (0.0): the system clock is not operating properly; timing may be inaccurate. (bit 0)
    pub const fn system_clock_failure(self) -> bool {
        self.0 & Self::SYSTEM_CLOCK_FAILURE != 0
    }

    /// Sets or clears `system_clock_failure` (bit 0).
    pub fn set_system_clock_failure(&mut self, v: bool) {
        if v {
            self.0 |= Self::SYSTEM_CLOCK_FAILURE;
        } else {
            self.0 &= !Self::SYSTEM_CLOCK_FAILURE;
        }
    }

    /// Bit 1 (0.1): supply voltage out of the recommended range, or an internal power fault. (bit 1)
    pub const fn power_fault(self) -> bool {
        self.0 & Self::POWER_FAULT != 0
    }

    /// Sets or clears `power_fault` (bit 1).
    pub fn set_power_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::POWER_FAULT;
        } else {
            self.0 &= !Self::POWER_FAULT;
        }
    }

    /// Bits 2-3 (0.2-0.3): reserved. Reserved. (bits 2..=3)
    pub const fn reserved_2_3(self) -> u8 {
        (self.0 & Self::RESERVED_2_3) >> 2
    }

    /// Sets `reserved_2_3` (bits 2..=3); higher bits of `v` are ignored.
    pub fn set_reserved_2_3(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED_2_3) | ((v << 2) & Self::RESERVED_2_3);
    }

    /// Bit 4 (0.4): firmware detected an unexpected or abnormal condition. (bit 4)
    pub const fn firmware_fault(self) -> bool {
        self.0 & Self::FIRMWARE_FAULT != 0
    }

    /// Sets or clears `firmware_fault` (bit 4).
    pub fn set_firmware_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::FIRMWARE_FAULT;
        } else {
            self.0 &= !Self::FIRMWARE_FAULT;
        }
    }

    /// Bit 5 (0.5): the system cannot keep up with the processing demand (e.g. too many descriptors). (bit 5)
    pub const fn timing_overload(self) -> bool {
        self.0 & Self::TIMING_OVERLOAD != 0
    }

    /// Sets or clears `timing_overload` (bit 5).
    pub fn set_timing_overload(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIMING_OVERLOAD;
        } else {
            self.0 &= !Self::TIMING_OVERLOAD;
        }
    }

    /// Bit 6 (0.6): a data buffer filled up and data may have been lost (bandwidth exceeded). (bit 6)
    pub const fn buffer_overrun(self) -> bool {
        self.0 & Self::BUFFER_OVERRUN != 0
    }

    /// Sets or clears `buffer_overrun` (bit 6).
    pub fn set_buffer_overrun(&mut self, v: bool) {
        if v {
            self.0 |= Self::BUFFER_OVERRUN;
        } else {
            self.0 &= !Self::BUFFER_OVERRUN;
        }
    }

    /// Bit 7 (0.7): reserved. Reserved. (bit 7)
    pub const fn reserved_7(self) -> bool {
        self.0 & Self::RESERVED_7 != 0
    }

    /// Sets or clears `reserved_7` (bit 7).
    pub fn set_reserved_7(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_7;
        } else {
            self.0 &= !Self::RESERVED_7;
        }
    }
}

impl crate::wire::Wire for Cv7ContinuousBitSystem0 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitSystem0 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 2: system, IMU and filter processes (bits 16-23).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitSystem2(pub u8);

impl Cv7ContinuousBitSystem2 {
    /// Mask of `imu_process_fault` (bit 0).
    pub const IMU_PROCESS_FAULT: u8 = 0x01;
    /// Mask of `imu_data_process_time_exceeded` (bit 1).
    pub const IMU_DATA_PROCESS_TIME_EXCEEDED: u8 = 0x02;
    /// Mask of `imu_data_rate_error` (bit 2).
    pub const IMU_DATA_RATE_ERROR: u8 = 0x04;
    /// Mask of `imu_stall` (bit 3).
    pub const IMU_STALL: u8 = 0x08;
    /// Mask of `filter_process_fault` (bits 4..=7).
    pub const FILTER_PROCESS_FAULT: u8 = 0xF0;
    /// Mask of `filter_major_cycle_fault` (bit 4).
    pub const FILTER_MAJOR_CYCLE_FAULT: u8 = 0x10;
    /// Mask of `filter_minor_cycle_fault` (bit 5).
    pub const FILTER_MINOR_CYCLE_FAULT: u8 = 0x20;
    /// Mask of `filter_data_rate_error` (bit 6).
    pub const FILTER_DATA_RATE_ERROR: u8 = 0x40;
    /// Mask of `filter_process_stall` (bit 7).
    pub const FILTER_PROCESS_STALL: u8 = 0x80;

    /// Bit 16 (2.0): the IMU subsystem is not running or did not start. (bit 0)
    pub const fn imu_process_fault(self) -> bool {
        self.0 & Self::IMU_PROCESS_FAULT != 0
    }

    /// Sets or clears `imu_process_fault` (bit 0).
    pub fn set_imu_process_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_PROCESS_FAULT;
        } else {
            self.0 &= !Self::IMU_PROCESS_FAULT;
        }
    }

    /// Bit 17 (2.1): IMU data processing took longer than allowed. (bit 1)
    pub const fn imu_data_process_time_exceeded(self) -> bool {
        self.0 & Self::IMU_DATA_PROCESS_TIME_EXCEEDED != 0
    }

    /// Sets or clears `imu_data_process_time_exceeded` (bit 1).
    pub fn set_imu_data_process_time_exceeded(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_DATA_PROCESS_TIME_EXCEEDED;
        } else {
            self.0 &= !Self::IMU_DATA_PROCESS_TIME_EXCEEDED;
        }
    }

    /// Bit 18 (2.2): IMU data is not produced at the expected base rate. (bit 2)
    pub const fn imu_data_rate_error(self) -> bool {
        self.0 & Self::IMU_DATA_RATE_ERROR != 0
    }

    /// Sets or clears `imu_data_rate_error` (bit 2).
    pub fn set_imu_data_rate_error(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_DATA_RATE_ERROR;
        } else {
            self.0 &= !Self::IMU_DATA_RATE_ERROR;
        }
    }

    /// Bit 19 (2.3): the IMU subsystem has stalled. (bit 3)
    pub const fn imu_stall(self) -> bool {
        self.0 & Self::IMU_STALL != 0
    }

    /// Sets or clears `imu_stall` (bit 3).
    pub fn set_imu_stall(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_STALL;
        } else {
            self.0 &= !Self::IMU_STALL;
        }
    }

    /// Bits 20-23 (2.4-2.7): any filter process fault (the four bits below). (bits 4..=7)
    pub const fn filter_process_fault(self) -> u8 {
        (self.0 & Self::FILTER_PROCESS_FAULT) >> 4
    }

    /// Sets `filter_process_fault` (bits 4..=7); higher bits of `v` are ignored.
    pub fn set_filter_process_fault(&mut self, v: u8) {
        self.0 = (self.0 & !Self::FILTER_PROCESS_FAULT) | ((v << 4) & Self::FILTER_PROCESS_FAULT);
    }

    /// Bit 20 (2.4): problem with the navigation filter major cycle. (bit 4)
    pub const fn filter_major_cycle_fault(self) -> bool {
        self.0 & Self::FILTER_MAJOR_CYCLE_FAULT != 0
    }

    /// Sets or clears `filter_major_cycle_fault` (bit 4).
    pub fn set_filter_major_cycle_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_MAJOR_CYCLE_FAULT;
        } else {
            self.0 &= !Self::FILTER_MAJOR_CYCLE_FAULT;
        }
    }

    /// Bit 21 (2.5): problem with the navigation filter minor cycle. (bit 5)
    pub const fn filter_minor_cycle_fault(self) -> bool {
        self.0 & Self::FILTER_MINOR_CYCLE_FAULT != 0
    }

    /// Sets or clears `filter_minor_cycle_fault` (bit 5).
    pub fn set_filter_minor_cycle_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_MINOR_CYCLE_FAULT;
        } else {
            self.0 &= !Self::FILTER_MINOR_CYCLE_FAULT;
        }
    }

    /// Bit 22 (2.6): a navigation filter process is not running at its base rate. (bit 6)
    pub const fn filter_data_rate_error(self) -> bool {
        self.0 & Self::FILTER_DATA_RATE_ERROR != 0
    }

    /// Sets or clears `filter_data_rate_error` (bit 6).
    pub fn set_filter_data_rate_error(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_DATA_RATE_ERROR;
        } else {
            self.0 &= !Self::FILTER_DATA_RATE_ERROR;
        }
    }

    /// Bit 23 (2.7): a navigation filter process has stalled. (bit 7)
    pub const fn filter_process_stall(self) -> bool {
        self.0 & Self::FILTER_PROCESS_STALL != 0
    }

    /// Sets or clears `filter_process_stall` (bit 7).
    pub fn set_filter_process_stall(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_PROCESS_STALL;
        } else {
            self.0 &= !Self::FILTER_PROCESS_STALL;
        }
    }
}

impl crate::wire::Wire for Cv7ContinuousBitSystem2 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitSystem2 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous BIT byte 3: system, GNSS processes (bits 24-31).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Cv7ContinuousBitSystem3(pub u8);

impl Cv7ContinuousBitSystem3 {
    /// Mask of `gnss_subsystem_fault` (bits 0..=3).
    pub const GNSS_SUBSYSTEM_FAULT: u8 = 0x0F;
    /// Mask of `gnss_main_process_fault` (bit 0).
    pub const GNSS_MAIN_PROCESS_FAULT: u8 = 0x01;
    /// Mask of `gnss_receiver_1_stall` (bit 1).
    pub const GNSS_RECEIVER_1_STALL: u8 = 0x02;
    /// Mask of `gnss_receiver_2_stall` (bit 2).
    pub const GNSS_RECEIVER_2_STALL: u8 = 0x04;
    /// Mask of `reserved_27` (bit 3).
    pub const RESERVED_27: u8 = 0x08;
    /// Mask of `reserved_28_31` (bits 4..=7).
    pub const RESERVED_28_31: u8 = 0xF0;

    /// Bits 24-27 (3.0-3.3): any GNSS subsystem fault (the bits below). (bits 0..=3)
    pub const fn gnss_subsystem_fault(self) -> u8 {
        self.0 & Self::GNSS_SUBSYSTEM_FAULT
    }

    /// Sets `gnss_subsystem_fault` (bits 0..=3); higher bits of `v` are ignored.
    pub fn set_gnss_subsystem_fault(&mut self, v: u8) {
        self.0 = (self.0 & !Self::GNSS_SUBSYSTEM_FAULT) | (v & Self::GNSS_SUBSYSTEM_FAULT);
    }

    /// Bit 24 (3.0): the master GNSS process has not run within its timeout. (bit 0)
    pub const fn gnss_main_process_fault(self) -> bool {
        self.0 & Self::GNSS_MAIN_PROCESS_FAULT != 0
    }

    /// Sets or clears `gnss_main_process_fault` (bit 0).
    pub fn set_gnss_main_process_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_MAIN_PROCESS_FAULT;
        } else {
            self.0 &= !Self::GNSS_MAIN_PROCESS_FAULT;
        }
    }

    /// Bit 25 (3.1): no data processed from internal receiver 1 within the timeout. (bit 1)
    pub const fn gnss_receiver_1_stall(self) -> bool {
        self.0 & Self::GNSS_RECEIVER_1_STALL != 0
    }

    /// Sets or clears `gnss_receiver_1_stall` (bit 1).
    pub fn set_gnss_receiver_1_stall(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_RECEIVER_1_STALL;
        } else {
            self.0 &= !Self::GNSS_RECEIVER_1_STALL;
        }
    }

    /// Bit 26 (3.2): no data processed from internal receiver 2 within the timeout. (bit 2)
    pub const fn gnss_receiver_2_stall(self) -> bool {
        self.0 & Self::GNSS_RECEIVER_2_STALL != 0
    }

    /// Sets or clears `gnss_receiver_2_stall` (bit 2).
    pub fn set_gnss_receiver_2_stall(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_RECEIVER_2_STALL;
        } else {
            self.0 &= !Self::GNSS_RECEIVER_2_STALL;
        }
    }

    /// Bit 27 (3.3): reserved. Reserved. (bit 3)
    pub const fn reserved_27(self) -> bool {
        self.0 & Self::RESERVED_27 != 0
    }

    /// Sets or clears `reserved_27` (bit 3).
    pub fn set_reserved_27(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_27;
        } else {
            self.0 &= !Self::RESERVED_27;
        }
    }

    /// Bits 28-31 (3.4-3.7): system reserved. Reserved. (bits 4..=7)
    pub const fn reserved_28_31(self) -> u8 {
        (self.0 & Self::RESERVED_28_31) >> 4
    }

    /// Sets `reserved_28_31` (bits 4..=7); higher bits of `v` are ignored.
    pub fn set_reserved_28_31(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED_28_31) | ((v << 4) & Self::RESERVED_28_31);
    }
}

impl crate::wire::Wire for Cv7ContinuousBitSystem3 {
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
impl crate::json_read::FromJson for Cv7ContinuousBitSystem3 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Descriptor and rate decimation. One entry of a message format list.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DescriptorRate {
    /// Data field descriptor.
    pub descriptor: u8,
    /// Rate decimation: the field is output at base rate / decimation.
    pub decimation: u16,
}

impl Default for DescriptorRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DescriptorRate {
    const ZERO: Self = Self {
        descriptor: <u8 as crate::wire::Wire>::ZERO,
        decimation: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(3);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_descriptor = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("descriptor"))?;
        let p_decimation = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("decimation"))?;
        Ok(Self {
            descriptor: p_descriptor,
            decimation: p_decimation,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.descriptor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("descriptor"))?;
        let v = &self.decimation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("decimation"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.descriptor;
        crate::json::key(w, &mut first, "descriptor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.decimation;
        crate::json::key(w, &mut first, "decimation")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DescriptorRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["descriptor", "decimation"])?;
        let p_descriptor = o.req("descriptor", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_decimation = o.req("decimation", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            descriptor: p_descriptor,
            decimation: p_decimation,
        })
    }
}

/// Device information. Firmware version and five 16-character identification strings, padded with spaces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceInfo {
    /// Firmware version number.
    pub firmware_version: u16,
    /// Model name.
    pub model_name: crate::wire::Str<16>,
    /// Model number.
    pub model_number: crate::wire::Str<16>,
    /// Serial number.
    pub serial_number: crate::wire::Str<16>,
    /// Lot number.
    pub lot_number: crate::wire::Str<16>,
    /// Device options (e.g. sensor ranges).
    pub device_options: crate::wire::Str<16>,
}

impl Default for DeviceInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceInfo {
    const ZERO: Self = Self {
        firmware_version: <u16 as crate::wire::Wire>::ZERO,
        model_name: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
        model_number: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
        serial_number: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
        lot_number: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
        device_options: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(82);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_firmware_version =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("firmware_version"))?;
        let p_model_name = <crate::wire::Str<16> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("model_name"))?;
        let p_model_number = <crate::wire::Str<16> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("model_number"))?;
        let p_serial_number = <crate::wire::Str<16> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("serial_number"))?;
        let p_lot_number = <crate::wire::Str<16> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("lot_number"))?;
        let p_device_options = <crate::wire::Str<16> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("device_options"))?;
        Ok(Self {
            firmware_version: p_firmware_version,
            model_name: p_model_name,
            model_number: p_model_number,
            serial_number: p_serial_number,
            lot_number: p_lot_number,
            device_options: p_device_options,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.firmware_version;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("firmware_version"))?;
        let v = &self.model_name;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("model_name"))?;
        let v = &self.model_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("model_number"))?;
        let v = &self.serial_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("serial_number"))?;
        let v = &self.lot_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("lot_number"))?;
        let v = &self.device_options;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("device_options"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.firmware_version;
        crate::json::key(w, &mut first, "firmware_version")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.model_name;
        crate::json::key(w, &mut first, "model_name")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.model_number;
        crate::json::key(w, &mut first, "model_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.serial_number;
        crate::json::key(w, &mut first, "serial_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.lot_number;
        crate::json::key(w, &mut first, "lot_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.device_options;
        crate::json::key(w, &mut first, "device_options")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "firmware_version",
                "model_name",
                "model_number",
                "serial_number",
                "lot_number",
                "device_options",
            ],
        )?;
        let p_firmware_version = o.req(
            "firmware_version",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_model_name = o.req(
            "model_name",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        let p_model_number = o.req(
            "model_number",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        let p_serial_number = o.req(
            "serial_number",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        let p_lot_number = o.req(
            "lot_number",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        let p_device_options = o.req(
            "device_options",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            firmware_version: p_firmware_version,
            model_name: p_model_name,
            model_number: p_model_number,
            serial_number: p_serial_number,
            lot_number: p_lot_number,
            device_options: p_device_options,
        })
    }
}

/// Device status selector.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct DeviceStatusSelector(pub u8);

impl DeviceStatusSelector {
    /// Basic status structure.
    pub const BASIC: Self = Self(1);
    /// Diagnostic status structure.
    pub const DIAGNOSTIC: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("basic"),
            2 => Some("diagnostic"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "basic" => Some(Self::BASIC),
            "diagnostic" => Some(Self::DIAGNOSTIC),
            _ => None,
        }
    }
}

impl core::fmt::Debug for DeviceStatusSelector {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "DeviceStatusSelector({} {})", self.0, name),
            None => write!(f, "DeviceStatusSelector({})", self.0),
        }
    }
}

impl crate::wire::Wire for DeviceStatusSelector {
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
impl crate::json_read::FromJson for DeviceStatusSelector {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Estimation control flags. Which optional states the Kalman filter estimates.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct EstimationControlFlags(pub u16);

impl EstimationControlFlags {
    /// Mask of `gyro_bias` (bit 0).
    pub const GYRO_BIAS: u16 = 0x0001;
    /// Mask of `accel_bias` (bit 1).
    pub const ACCEL_BIAS: u16 = 0x0002;
    /// Mask of `gyro_scale_factor` (bit 2).
    pub const GYRO_SCALE_FACTOR: u16 = 0x0004;
    /// Mask of `accel_scale_factor` (bit 3).
    pub const ACCEL_SCALE_FACTOR: u16 = 0x0008;
    /// Mask of `antenna_offset` (bit 4).
    pub const ANTENNA_OFFSET: u16 = 0x0010;
    /// Mask of `hard_iron_auto_cal` (bit 5).
    pub const HARD_IRON_AUTO_CAL: u16 = 0x0020;
    /// Mask of `soft_iron_auto_cal` (bit 6).
    pub const SOFT_IRON_AUTO_CAL: u16 = 0x0040;
    /// Mask of `reserved` (bits 7..=15).
    pub const RESERVED: u16 = 0xFF80;

    /// Estimate gyro bias (recommended). (bit 0)
    pub const fn gyro_bias(self) -> bool {
        self.0 & Self::GYRO_BIAS != 0
    }

    /// Sets or clears `gyro_bias` (bit 0).
    pub fn set_gyro_bias(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYRO_BIAS;
        } else {
            self.0 &= !Self::GYRO_BIAS;
        }
    }

    /// Estimate accelerometer bias (recommended). (bit 1)
    pub const fn accel_bias(self) -> bool {
        self.0 & Self::ACCEL_BIAS != 0
    }

    /// Sets or clears `accel_bias` (bit 1).
    pub fn set_accel_bias(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCEL_BIAS;
        } else {
            self.0 &= !Self::ACCEL_BIAS;
        }
    }

    /// Estimate gyro scale factor (optional). (bit 2)
    pub const fn gyro_scale_factor(self) -> bool {
        self.0 & Self::GYRO_SCALE_FACTOR != 0
    }

    /// Sets or clears `gyro_scale_factor` (bit 2).
    pub fn set_gyro_scale_factor(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYRO_SCALE_FACTOR;
        } else {
            self.0 &= !Self::GYRO_SCALE_FACTOR;
        }
    }

    /// Estimate accelerometer scale factor (optional). (bit 3)
    pub const fn accel_scale_factor(self) -> bool {
        self.0 & Self::ACCEL_SCALE_FACTOR != 0
    }

    /// Sets or clears `accel_scale_factor` (bit 3).
    pub fn set_accel_scale_factor(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCEL_SCALE_FACTOR;
        } else {
            self.0 &= !Self::ACCEL_SCALE_FACTOR;
        }
    }

    /// Estimate the GNSS antenna offset (optional). (bit 4)
    pub const fn antenna_offset(self) -> bool {
        self.0 & Self::ANTENNA_OFFSET != 0
    }

    /// Sets or clears `antenna_offset` (bit 4).
    pub fn set_antenna_offset(&mut self, v: bool) {
        if v {
            self.0 |= Self::ANTENNA_OFFSET;
        } else {
            self.0 &= !Self::ANTENNA_OFFSET;
        }
    }

    /// Hard iron auto-calibration (optional). (bit 5)
    pub const fn hard_iron_auto_cal(self) -> bool {
        self.0 & Self::HARD_IRON_AUTO_CAL != 0
    }

    /// Sets or clears `hard_iron_auto_cal` (bit 5).
    pub fn set_hard_iron_auto_cal(&mut self, v: bool) {
        if v {
            self.0 |= Self::HARD_IRON_AUTO_CAL;
        } else {
            self.0 &= !Self::HARD_IRON_AUTO_CAL;
        }
    }

    /// Soft iron auto-calibration (optional). (bit 6)
    pub const fn soft_iron_auto_cal(self) -> bool {
        self.0 & Self::SOFT_IRON_AUTO_CAL != 0
    }

    /// Sets or clears `soft_iron_auto_cal` (bit 6).
    pub fn set_soft_iron_auto_cal(&mut self, v: bool) {
        if v {
            self.0 |= Self::SOFT_IRON_AUTO_CAL;
        } else {
            self.0 &= !Self::SOFT_IRON_AUTO_CAL;
        }
    }

    /// Not named by the manual. Reserved. (bits 7..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 7
    }

    /// Sets `reserved` (bits 7..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 7) & Self::RESERVED);
    }
}

impl crate::wire::Wire for EstimationControlFlags {
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
impl crate::json_read::FromJson for EstimationControlFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Event trigger control mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct EventControlMode(pub u8);

impl EventControlMode {
    /// Trigger is disabled.
    pub const DISABLED: Self = Self(0);
    /// Trigger is enabled and will work normally.
    pub const ENABLED: Self = Self(1);
    /// Forces the trigger to the active state for testing purposes.
    pub const TEST: Self = Self(2);
    /// Trigger is forced active for one event cycle only, then reverts.
    pub const TEST_PULSE: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("disabled"),
            1 => Some("enabled"),
            2 => Some("test"),
            3 => Some("test_pulse"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "disabled" => Some(Self::DISABLED),
            "enabled" => Some(Self::ENABLED),
            "test" => Some(Self::TEST),
            "test_pulse" => Some(Self::TEST_PULSE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for EventControlMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "EventControlMode({} {})", self.0, name),
            None => write!(f, "EventControlMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for EventControlMode {
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
impl crate::json_read::FromJson for EventControlMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// External heading type. Reference of an externally supplied heading angle.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ExternalHeadingType(pub u8);

impl ExternalHeadingType {
    /// True heading (from true north).
    pub const TRUE_HEADING: Self = Self(1);
    /// Magnetic heading (from magnetic north).
    pub const MAGNETIC_HEADING: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("true_heading"),
            2 => Some("magnetic_heading"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "true_heading" => Some(Self::TRUE_HEADING),
            "magnetic_heading" => Some(Self::MAGNETIC_HEADING),
            _ => None,
        }
    }
}

impl core::fmt::Debug for ExternalHeadingType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "ExternalHeadingType({} {})", self.0, name),
            None => write!(f, "ExternalHeadingType({})", self.0),
        }
    }
}

impl crate::wire::Wire for ExternalHeadingType {
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
impl crate::json_read::FromJson for ExternalHeadingType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// External time delta valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ExternalTimeDeltaValidFlags(pub u16);

impl ExternalTimeDeltaValidFlags {
    /// Mask of `dt_nanos` (bit 0).
    pub const DT_NANOS: u16 = 0x0001;
    /// Mask of `reserved` (bits 1..=15).
    pub const RESERVED: u16 = 0xFFFE;

    /// The delta is valid. (bit 0)
    pub const fn dt_nanos(self) -> bool {
        self.0 & Self::DT_NANOS != 0
    }

    /// Sets or clears `dt_nanos` (bit 0).
    pub fn set_dt_nanos(&mut self, v: bool) {
        if v {
            self.0 |= Self::DT_NANOS;
        } else {
            self.0 &= !Self::DT_NANOS;
        }
    }

    /// Not listed. Reserved. (bits 1..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 1
    }

    /// Sets `reserved` (bits 1..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 1) & Self::RESERVED);
    }
}

impl crate::wire::Wire for ExternalTimeDeltaValidFlags {
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
impl crate::json_read::FromJson for ExternalTimeDeltaValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// External timestamp valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ExternalTimestampValidFlags(pub u16);

impl ExternalTimestampValidFlags {
    /// Mask of `nanoseconds` (bit 0).
    pub const NANOSECONDS: u16 = 0x0001;
    /// Mask of `reserved` (bits 1..=15).
    pub const RESERVED: u16 = 0xFFFE;

    /// The nanoseconds value is valid (external clock synchronised via PPS). (bit 0)
    pub const fn nanoseconds(self) -> bool {
        self.0 & Self::NANOSECONDS != 0
    }

    /// Sets or clears `nanoseconds` (bit 0).
    pub fn set_nanoseconds(&mut self, v: bool) {
        if v {
            self.0 |= Self::NANOSECONDS;
        } else {
            self.0 &= !Self::NANOSECONDS;
        }
    }

    /// Not listed. Reserved. (bits 1..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 1
    }

    /// Sets `reserved` (bits 1..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 1) & Self::RESERVED);
    }
}

impl crate::wire::Wire for ExternalTimestampValidFlags {
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
impl crate::json_read::FromJson for ExternalTimestampValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Factory streaming action.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FactoryStreamingAction(pub u8);

impl FactoryStreamingAction {
    /// Replace the message formats, dropping the descriptors already there.
    pub const OVERWRITE: Self = Self(0);
    /// Merge the support descriptors into the existing formats (order may change).
    pub const MERGE: Self = Self(1);
    /// Append the support descriptors to the existing formats (duplicates possible).
    pub const ADD: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("overwrite"),
            1 => Some("merge"),
            2 => Some("add"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "overwrite" => Some(Self::OVERWRITE),
            "merge" => Some(Self::MERGE),
            "add" => Some(Self::ADD),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FactoryStreamingAction {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FactoryStreamingAction({} {})", self.0, name),
            None => write!(f, "FactoryStreamingAction({})", self.0),
        }
    }
}

impl crate::wire::Wire for FactoryStreamingAction {
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
impl crate::json_read::FromJson for FactoryStreamingAction {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding measurement indicator. State of one aiding measurement over the last measurement interval.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterAidingMeasurementIndicator(pub u8);

impl FilterAidingMeasurementIndicator {
    /// Mask of `enabled` (bit 0).
    pub const ENABLED: u8 = 0x01;
    /// Mask of `used` (bit 1).
    pub const USED: u8 = 0x02;
    /// Mask of `residual_high_warning` (bit 2).
    pub const RESIDUAL_HIGH_WARNING: u8 = 0x04;
    /// Mask of `sample_time_warning` (bit 3).
    pub const SAMPLE_TIME_WARNING: u8 = 0x08;
    /// Mask of `configuration_error` (bit 4).
    pub const CONFIGURATION_ERROR: u8 = 0x10;
    /// Mask of `max_num_meas_exceeded` (bit 5).
    pub const MAX_NUM_MEAS_EXCEEDED: u8 = 0x20;

    /// The measurement is enabled. (bit 0)
    pub const fn enabled(self) -> bool {
        self.0 & Self::ENABLED != 0
    }

    /// Sets or clears `enabled` (bit 0).
    pub fn set_enabled(&mut self, v: bool) {
        if v {
            self.0 |= Self::ENABLED;
        } else {
            self.0 &= !Self::ENABLED;
        }
    }

    /// The measurement was used by the filter. (bit 1)
    pub const fn used(self) -> bool {
        self.0 & Self::USED != 0
    }

    /// Sets or clears `used` (bit 1).
    pub fn set_used(&mut self, v: bool) {
        if v {
            self.0 |= Self::USED;
        } else {
            self.0 &= !Self::USED;
        }
    }

    /// Measurement residual is high. (bit 2)
    pub const fn residual_high_warning(self) -> bool {
        self.0 & Self::RESIDUAL_HIGH_WARNING != 0
    }

    /// Sets or clears `residual_high_warning` (bit 2).
    pub fn set_residual_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESIDUAL_HIGH_WARNING;
        } else {
            self.0 &= !Self::RESIDUAL_HIGH_WARNING;
        }
    }

    /// Problem with the measurement's sample time. (bit 3)
    pub const fn sample_time_warning(self) -> bool {
        self.0 & Self::SAMPLE_TIME_WARNING != 0
    }

    /// Sets or clears `sample_time_warning` (bit 3).
    pub fn set_sample_time_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::SAMPLE_TIME_WARNING;
        } else {
            self.0 &= !Self::SAMPLE_TIME_WARNING;
        }
    }

    /// The measurement is misconfigured. (bit 4)
    pub const fn configuration_error(self) -> bool {
        self.0 & Self::CONFIGURATION_ERROR != 0
    }

    /// Sets or clears `configuration_error` (bit 4).
    pub fn set_configuration_error(&mut self, v: bool) {
        if v {
            self.0 |= Self::CONFIGURATION_ERROR;
        } else {
            self.0 &= !Self::CONFIGURATION_ERROR;
        }
    }

    /// More measurements than the filter can process. (bit 5)
    pub const fn max_num_meas_exceeded(self) -> bool {
        self.0 & Self::MAX_NUM_MEAS_EXCEEDED != 0
    }

    /// Sets or clears `max_num_meas_exceeded` (bit 5).
    pub fn set_max_num_meas_exceeded(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAX_NUM_MEAS_EXCEEDED;
        } else {
            self.0 &= !Self::MAX_NUM_MEAS_EXCEEDED;
        }
    }
}

impl crate::wire::Wire for FilterAidingMeasurementIndicator {
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
impl crate::json_read::FromJson for FilterAidingMeasurementIndicator {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Aiding measurement type. Which aiding measurement an Aiding Measurement Summary (0x82,0x46) describes. Values 0x20 and above are the measurements commanded through the Aiding command set (0x13); their value is the descriptor of that command.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterAidingMeasurementType(pub u8);

impl FilterAidingMeasurementType {
    /// GNSS receiver measurement.
    pub const GNSS: Self = Self(1);
    /// GNSS dual-antenna heading.
    pub const DUAL_ANTENNA: Self = Self(2);
    /// Heading measurement.
    pub const HEADING: Self = Self(3);
    /// Pressure (barometric altitude).
    pub const PRESSURE: Self = Self(4);
    /// Magnetometer.
    pub const MAGNETOMETER: Self = Self(5);
    /// Speed sensor (odometer).
    pub const SPEED: Self = Self(6);
    /// ECEF position aiding command (0x13,0x21).
    pub const AIDING_POS_ECEF: Self = Self(33);
    /// LLH position aiding command (0x13,0x22).
    pub const AIDING_POS_LLH: Self = Self(34);
    /// Height above ellipsoid aiding command (0x13,0x23).
    pub const AIDING_HEIGHT_ABOVE_ELLIPSOID: Self = Self(35);
    /// ECEF velocity aiding command (0x13,0x28).
    pub const AIDING_VEL_ECEF: Self = Self(40);
    /// NED velocity aiding command (0x13,0x29).
    pub const AIDING_VEL_NED: Self = Self(41);
    /// Body-frame velocity aiding command (0x13,0x2A).
    pub const AIDING_VEL_BODY_FRAME: Self = Self(42);
    /// True heading aiding command (0x13,0x31).
    pub const AIDING_HEADING_TRUE: Self = Self(49);
    /// Magnetic field aiding command (0x13,0x32).
    pub const AIDING_MAGNETIC_FIELD: Self = Self(50);
    /// Pressure aiding command (0x13,0x33).
    pub const AIDING_PRESSURE: Self = Self(51);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("gnss"),
            2 => Some("dual_antenna"),
            3 => Some("heading"),
            4 => Some("pressure"),
            5 => Some("magnetometer"),
            6 => Some("speed"),
            33 => Some("aiding_pos_ecef"),
            34 => Some("aiding_pos_llh"),
            35 => Some("aiding_height_above_ellipsoid"),
            40 => Some("aiding_vel_ecef"),
            41 => Some("aiding_vel_ned"),
            42 => Some("aiding_vel_body_frame"),
            49 => Some("aiding_heading_true"),
            50 => Some("aiding_magnetic_field"),
            51 => Some("aiding_pressure"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "gnss" => Some(Self::GNSS),
            "dual_antenna" => Some(Self::DUAL_ANTENNA),
            "heading" => Some(Self::HEADING),
            "pressure" => Some(Self::PRESSURE),
            "magnetometer" => Some(Self::MAGNETOMETER),
            "speed" => Some(Self::SPEED),
            "aiding_pos_ecef" => Some(Self::AIDING_POS_ECEF),
            "aiding_pos_llh" => Some(Self::AIDING_POS_LLH),
            "aiding_height_above_ellipsoid" => Some(Self::AIDING_HEIGHT_ABOVE_ELLIPSOID),
            "aiding_vel_ecef" => Some(Self::AIDING_VEL_ECEF),
            "aiding_vel_ned" => Some(Self::AIDING_VEL_NED),
            "aiding_vel_body_frame" => Some(Self::AIDING_VEL_BODY_FRAME),
            "aiding_heading_true" => Some(Self::AIDING_HEADING_TRUE),
            "aiding_magnetic_field" => Some(Self::AIDING_MAGNETIC_FIELD),
            "aiding_pressure" => Some(Self::AIDING_PRESSURE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterAidingMeasurementType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterAidingMeasurementType({} {})", self.0, name),
            None => write!(f, "FilterAidingMeasurementType({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterAidingMeasurementType {
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
impl crate::json_read::FromJson for FilterAidingMeasurementType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Dual-antenna fix type. Kind of GNSS dual-antenna heading solution.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterDualAntennaFixType(pub u8);

impl FilterDualAntennaFixType {
    /// No dual-antenna fix.
    pub const FIX_NONE: Self = Self(0);
    /// Dual-antenna float solution.
    pub const FIX_DA_FLOAT: Self = Self(1);
    /// Dual-antenna fixed (integer) solution.
    pub const FIX_DA_FIXED: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("fix_none"),
            1 => Some("fix_da_float"),
            2 => Some("fix_da_fixed"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "fix_none" => Some(Self::FIX_NONE),
            "fix_da_float" => Some(Self::FIX_DA_FLOAT),
            "fix_da_fixed" => Some(Self::FIX_DA_FIXED),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterDualAntennaFixType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterDualAntennaFixType({} {})", self.0, name),
            None => write!(f, "FilterDualAntennaFixType({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterDualAntennaFixType {
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
impl crate::json_read::FromJson for FilterDualAntennaFixType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Dual-antenna status flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterDualAntennaStatusFlags(pub u16);

impl FilterDualAntennaStatusFlags {
    /// Mask of `rcv_1_data_valid` (bit 0).
    pub const RCV_1_DATA_VALID: u16 = 0x0001;
    /// Mask of `rcv_2_data_valid` (bit 1).
    pub const RCV_2_DATA_VALID: u16 = 0x0002;
    /// Mask of `antenna_offsets_valid` (bit 2).
    pub const ANTENNA_OFFSETS_VALID: u16 = 0x0004;

    /// Data from receiver 1 are valid. (bit 0)
    pub const fn rcv_1_data_valid(self) -> bool {
        self.0 & Self::RCV_1_DATA_VALID != 0
    }

    /// Sets or clears `rcv_1_data_valid` (bit 0).
    pub fn set_rcv_1_data_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::RCV_1_DATA_VALID;
        } else {
            self.0 &= !Self::RCV_1_DATA_VALID;
        }
    }

    /// Data from receiver 2 are valid. (bit 1)
    pub const fn rcv_2_data_valid(self) -> bool {
        self.0 & Self::RCV_2_DATA_VALID != 0
    }

    /// Sets or clears `rcv_2_data_valid` (bit 1).
    pub fn set_rcv_2_data_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::RCV_2_DATA_VALID;
        } else {
            self.0 &= !Self::RCV_2_DATA_VALID;
        }
    }

    /// The antenna offsets are valid. (bit 2)
    pub const fn antenna_offsets_valid(self) -> bool {
        self.0 & Self::ANTENNA_OFFSETS_VALID != 0
    }

    /// Sets or clears `antenna_offsets_valid` (bit 2).
    pub fn set_antenna_offsets_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::ANTENNA_OFFSETS_VALID;
        } else {
            self.0 &= !Self::ANTENNA_OFFSETS_VALID;
        }
    }
}

impl crate::wire::Wire for FilterDualAntennaStatusFlags {
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
impl crate::json_read::FromJson for FilterDualAntennaStatusFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter dynamics mode (3DM-CV7). Dynamics mode reported in Status (0x82,0x10) by the CV7 (GQ7-family filter).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterDynamicsModeCv7(pub u16);

impl FilterDynamicsModeCv7 {
    /// Default dynamics mode (printed GQ7_DEFAULT).
    pub const DEFAULT: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("default"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "default" => Some(Self::DEFAULT),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterDynamicsModeCv7 {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterDynamicsModeCv7({} {})", self.0, name),
            None => write!(f, "FilterDynamicsModeCv7({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterDynamicsModeCv7 {
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
impl crate::json_read::FromJson for FilterDynamicsModeCv7 {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter dynamics mode (3DM-GX5-45). Vehicle dynamics mode the GX5-45 filter runs with, as reported in Filter Status (0x82,0x10).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterDynamicsModeGx5(pub u16);

impl FilterDynamicsModeGx5 {
    /// Portable (low-acceleration applications).
    pub const PORTABLE: Self = Self(1);
    /// Automotive (wheeled vehicles, low vertical acceleration).
    pub const AUTOMOTIVE: Self = Self(2);
    /// Airborne (up to 2 g).
    pub const AIRBORNE: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("portable"),
            2 => Some("automotive"),
            3 => Some("airborne"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "portable" => Some(Self::PORTABLE),
            "automotive" => Some(Self::AUTOMOTIVE),
            "airborne" => Some(Self::AIRBORNE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterDynamicsModeGx5 {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterDynamicsModeGx5({} {})", self.0, name),
            None => write!(f, "FilterDynamicsModeGx5({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterDynamicsModeGx5 {
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
impl crate::json_read::FromJson for FilterDynamicsModeGx5 {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS position aiding status. What the filter does with the measurements of one GNSS receiver.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterGnssAidingStatusFlags(pub u16);

impl FilterGnssAidingStatusFlags {
    /// Mask of `tight_coupling` (bit 0).
    pub const TIGHT_COUPLING: u16 = 0x0001;
    /// Mask of `differential` (bit 1).
    pub const DIFFERENTIAL: u16 = 0x0002;
    /// Mask of `integer_fix` (bit 2).
    pub const INTEGER_FIX: u16 = 0x0004;
    /// Mask of `gps_l1` (bit 3).
    pub const GPS_L1: u16 = 0x0008;
    /// Mask of `gps_l2` (bit 4).
    pub const GPS_L2: u16 = 0x0010;
    /// Mask of `gps_l5` (bit 5).
    pub const GPS_L5: u16 = 0x0020;
    /// Mask of `glo_l1` (bit 6).
    pub const GLO_L1: u16 = 0x0040;
    /// Mask of `glo_l2` (bit 7).
    pub const GLO_L2: u16 = 0x0080;
    /// Mask of `gal_e1` (bit 8).
    pub const GAL_E1: u16 = 0x0100;
    /// Mask of `gal_e5` (bit 9).
    pub const GAL_E5: u16 = 0x0200;
    /// Mask of `gal_e6` (bit 10).
    pub const GAL_E6: u16 = 0x0400;
    /// Mask of `bei_b1` (bit 11).
    pub const BEI_B1: u16 = 0x0800;
    /// Mask of `bei_b2` (bit 12).
    pub const BEI_B2: u16 = 0x1000;
    /// Mask of `bei_b3` (bit 13).
    pub const BEI_B3: u16 = 0x2000;
    /// Mask of `no_fix` (bit 14).
    pub const NO_FIX: u16 = 0x4000;
    /// Mask of `config_error` (bit 15).
    pub const CONFIG_ERROR: u16 = 0x8000;

    /// The filter is processing raw range information from this receiver. (bit 0)
    pub const fn tight_coupling(self) -> bool {
        self.0 & Self::TIGHT_COUPLING != 0
    }

    /// Sets or clears `tight_coupling` (bit 0).
    pub fn set_tight_coupling(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIGHT_COUPLING;
        } else {
            self.0 &= !Self::TIGHT_COUPLING;
        }
    }

    /// The filter is processing RTK corrections from this receiver. (bit 1)
    pub const fn differential(self) -> bool {
        self.0 & Self::DIFFERENTIAL != 0
    }

    /// Sets or clears `differential` (bit 1).
    pub fn set_differential(&mut self, v: bool) {
        if v {
            self.0 |= Self::DIFFERENTIAL;
        } else {
            self.0 &= !Self::DIFFERENTIAL;
        }
    }

    /// The filter has an RTK integer fix from this receiver. (bit 2)
    pub const fn integer_fix(self) -> bool {
        self.0 & Self::INTEGER_FIX != 0
    }

    /// Sets or clears `integer_fix` (bit 2).
    pub fn set_integer_fix(&mut self, v: bool) {
        if v {
            self.0 |= Self::INTEGER_FIX;
        } else {
            self.0 &= !Self::INTEGER_FIX;
        }
    }

    /// GPS L1 measurements used. (bit 3)
    pub const fn gps_l1(self) -> bool {
        self.0 & Self::GPS_L1 != 0
    }

    /// Sets or clears `gps_l1` (bit 3).
    pub fn set_gps_l1(&mut self, v: bool) {
        if v {
            self.0 |= Self::GPS_L1;
        } else {
            self.0 &= !Self::GPS_L1;
        }
    }

    /// GPS L2 measurements used. (bit 4)
    pub const fn gps_l2(self) -> bool {
        self.0 & Self::GPS_L2 != 0
    }

    /// Sets or clears `gps_l2` (bit 4).
    pub fn set_gps_l2(&mut self, v: bool) {
        if v {
            self.0 |= Self::GPS_L2;
        } else {
            self.0 &= !Self::GPS_L2;
        }
    }

    /// GPS L5 measurements used. (bit 5)
    pub const fn gps_l5(self) -> bool {
        self.0 & Self::GPS_L5 != 0
    }

    /// Sets or clears `gps_l5` (bit 5).
    pub fn set_gps_l5(&mut self, v: bool) {
        if v {
            self.0 |= Self::GPS_L5;
        } else {
            self.0 &= !Self::GPS_L5;
        }
    }

    /// GLONASS L1 measurements used. (bit 6)
    pub const fn glo_l1(self) -> bool {
        self.0 & Self::GLO_L1 != 0
    }

    /// Sets or clears `glo_l1` (bit 6).
    pub fn set_glo_l1(&mut self, v: bool) {
        if v {
            self.0 |= Self::GLO_L1;
        } else {
            self.0 &= !Self::GLO_L1;
        }
    }

    /// GLONASS L2 measurements used. (bit 7)
    pub const fn glo_l2(self) -> bool {
        self.0 & Self::GLO_L2 != 0
    }

    /// Sets or clears `glo_l2` (bit 7).
    pub fn set_glo_l2(&mut self, v: bool) {
        if v {
            self.0 |= Self::GLO_L2;
        } else {
            self.0 &= !Self::GLO_L2;
        }
    }

    /// Galileo E1 measurements used. (bit 8)
    pub const fn gal_e1(self) -> bool {
        self.0 & Self::GAL_E1 != 0
    }

    /// Sets or clears `gal_e1` (bit 8).
    pub fn set_gal_e1(&mut self, v: bool) {
        if v {
            self.0 |= Self::GAL_E1;
        } else {
            self.0 &= !Self::GAL_E1;
        }
    }

    /// Galileo E5 measurements used. (bit 9)
    pub const fn gal_e5(self) -> bool {
        self.0 & Self::GAL_E5 != 0
    }

    /// Sets or clears `gal_e5` (bit 9).
    pub fn set_gal_e5(&mut self, v: bool) {
        if v {
            self.0 |= Self::GAL_E5;
        } else {
            self.0 &= !Self::GAL_E5;
        }
    }

    /// Galileo E6 measurements used. (bit 10)
    pub const fn gal_e6(self) -> bool {
        self.0 & Self::GAL_E6 != 0
    }

    /// Sets or clears `gal_e6` (bit 10).
    pub fn set_gal_e6(&mut self, v: bool) {
        if v {
            self.0 |= Self::GAL_E6;
        } else {
            self.0 &= !Self::GAL_E6;
        }
    }

    /// BeiDou B1 measurements used. (bit 11)
    pub const fn bei_b1(self) -> bool {
        self.0 & Self::BEI_B1 != 0
    }

    /// Sets or clears `bei_b1` (bit 11).
    pub fn set_bei_b1(&mut self, v: bool) {
        if v {
            self.0 |= Self::BEI_B1;
        } else {
            self.0 &= !Self::BEI_B1;
        }
    }

    /// BeiDou B2 measurements used. (bit 12)
    pub const fn bei_b2(self) -> bool {
        self.0 & Self::BEI_B2 != 0
    }

    /// Sets or clears `bei_b2` (bit 12).
    pub fn set_bei_b2(&mut self, v: bool) {
        if v {
            self.0 |= Self::BEI_B2;
        } else {
            self.0 &= !Self::BEI_B2;
        }
    }

    /// BeiDou B3 measurements used. (bit 13)
    pub const fn bei_b3(self) -> bool {
        self.0 & Self::BEI_B3 != 0
    }

    /// Sets or clears `bei_b3` (bit 13).
    pub fn set_bei_b3(&mut self, v: bool) {
        if v {
            self.0 |= Self::BEI_B3;
        } else {
            self.0 &= !Self::BEI_B3;
        }
    }

    /// This receiver reports no position fix. (bit 14)
    pub const fn no_fix(self) -> bool {
        self.0 & Self::NO_FIX != 0
    }

    /// Sets or clears `no_fix` (bit 14).
    pub fn set_no_fix(&mut self, v: bool) {
        if v {
            self.0 |= Self::NO_FIX;
        } else {
            self.0 &= !Self::NO_FIX;
        }
    }

    /// Probably a problem with this receiver's antenna offset. (bit 15)
    pub const fn config_error(self) -> bool {
        self.0 & Self::CONFIG_ERROR != 0
    }

    /// Sets or clears `config_error` (bit 15).
    pub fn set_config_error(&mut self, v: bool) {
        if v {
            self.0 |= Self::CONFIG_ERROR;
        } else {
            self.0 &= !Self::CONFIG_ERROR;
        }
    }
}

impl crate::wire::Wire for FilterGnssAidingStatusFlags {
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
impl crate::json_read::FromJson for FilterGnssAidingStatusFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter GNSS source. Where the filter takes its GNSS position and velocity updates from.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterGnssSource(pub u8);

impl FilterGnssSource {
    /// The internal GNSS receiver(s) (GX5-45: Internal GNSS; CV7: ALL_INT, all internal receivers).
    pub const ALL_INTERNAL: Self = Self(1);
    /// External GNSS messages supplied by the user (GX5-45: External GNSS Update 0x0D,0x16).
    pub const EXTERNAL: Self = Self(2);
    /// Internal GNSS receiver 1 only. Devices: cv7_ins.
    pub const INTERNAL_1: Self = Self(3);
    /// Internal GNSS receiver 2 only. Devices: cv7_ins.
    pub const INTERNAL_2: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("all_internal"),
            2 => Some("external"),
            3 => Some("internal_1"),
            4 => Some("internal_2"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "all_internal" => Some(Self::ALL_INTERNAL),
            "external" => Some(Self::EXTERNAL),
            "internal_1" => Some(Self::INTERNAL_1),
            "internal_2" => Some(Self::INTERNAL_2),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterGnssSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterGnssSource({} {})", self.0, name),
            None => write!(f, "FilterGnssSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterGnssSource {
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
impl crate::json_read::FromJson for FilterGnssSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Heading update sources in use. Sources currently providing heading updates; 0 means none (heading updates disabled).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterHeadingSourceFlags(pub u16);

impl FilterHeadingSourceFlags {
    /// Mask of `magnetometer` (bit 0).
    pub const MAGNETOMETER: u16 = 0x0001;
    /// Mask of `gnss_velocity` (bit 1).
    pub const GNSS_VELOCITY: u16 = 0x0002;
    /// Mask of `external` (bit 2).
    pub const EXTERNAL: u16 = 0x0004;

    /// Internal magnetometer. (bit 0)
    pub const fn magnetometer(self) -> bool {
        self.0 & Self::MAGNETOMETER != 0
    }

    /// Sets or clears `magnetometer` (bit 0).
    pub fn set_magnetometer(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAGNETOMETER;
        } else {
            self.0 &= !Self::MAGNETOMETER;
        }
    }

    /// GNSS velocity vector. (bit 1)
    pub const fn gnss_velocity(self) -> bool {
        self.0 & Self::GNSS_VELOCITY != 0
    }

    /// Sets or clears `gnss_velocity` (bit 1).
    pub fn set_gnss_velocity(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_VELOCITY;
        } else {
            self.0 &= !Self::GNSS_VELOCITY;
        }
    }

    /// External Heading Update messages (0x0D,0x17), with or without timestamp (0x0D,0x1F). (bit 2)
    pub const fn external(self) -> bool {
        self.0 & Self::EXTERNAL != 0
    }

    /// Sets or clears `external` (bit 2).
    pub fn set_external(&mut self, v: bool) {
        if v {
            self.0 |= Self::EXTERNAL;
        } else {
            self.0 &= !Self::EXTERNAL;
        }
    }
}

impl crate::wire::Wire for FilterHeadingSourceFlags {
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
impl crate::json_read::FromJson for FilterHeadingSourceFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Heading update state valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterHeadingUpdateValidFlags(pub u16);

impl FilterHeadingUpdateValidFlags {
    /// Mask of `updated_within_2s` (bit 0).
    pub const UPDATED_WITHIN_2S: u16 = 0x0001;

    /// The heading update source provided data within the last 2 seconds (0: no update for 2 seconds). (bit 0)
    pub const fn updated_within_2s(self) -> bool {
        self.0 & Self::UPDATED_WITHIN_2S != 0
    }

    /// Sets or clears `updated_within_2s` (bit 0).
    pub fn set_updated_within_2s(&mut self, v: bool) {
        if v {
            self.0 |= Self::UPDATED_WITHIN_2S;
        } else {
            self.0 &= !Self::UPDATED_WITHIN_2S;
        }
    }
}

impl crate::wire::Wire for FilterHeadingUpdateValidFlags {
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
impl crate::json_read::FromJson for FilterHeadingUpdateValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Navigation filter initial condition source.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterInitialConditionSource(pub u8);

impl FilterInitialConditionSource {
    /// Automatic position, velocity and attitude.
    pub const AUTO_POS_VEL_ATT: Self = Self(0);
    /// Automatic position, velocity, pitch and roll; heading as specified.
    pub const AUTO_POS_VEL_PITCH_ROLL: Self = Self(1);
    /// Automatic position and velocity; attitude fully user-specified.
    pub const AUTO_POS_VEL: Self = Self(2);
    /// User-specified position, velocity and attitude.
    pub const MANUAL: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("auto_pos_vel_att"),
            1 => Some("auto_pos_vel_pitch_roll"),
            2 => Some("auto_pos_vel"),
            3 => Some("manual"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "auto_pos_vel_att" => Some(Self::AUTO_POS_VEL_ATT),
            "auto_pos_vel_pitch_roll" => Some(Self::AUTO_POS_VEL_PITCH_ROLL),
            "auto_pos_vel" => Some(Self::AUTO_POS_VEL),
            "manual" => Some(Self::MANUAL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterInitialConditionSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterInitialConditionSource({} {})", self.0, name),
            None => write!(f, "FilterInitialConditionSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterInitialConditionSource {
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
impl crate::json_read::FromJson for FilterInitialConditionSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter mode (3DM-CV7). Mode the CV7 navigation filter has reached, reported as the filter state in Status (0x82,0x10); it depends on the initial conditions the filter was given.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterModeCv7(pub u16);

impl FilterModeCv7 {
    /// Initialization: initial conditions incomplete or invalid, or waiting for user input.
    pub const INIT: Self = Self(1);
    /// Vertical gyro: valid pitch and roll, heading relative to the initial heading.
    pub const VERT_GYRO: Self = Self(2);
    /// AHRS: as vertical gyro, with an absolute heading reference.
    pub const AHRS: Self = Self(3);
    /// Full navigation: valid position, velocity, pitch, roll and heading.
    pub const FULL_NAV: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("init"),
            2 => Some("vert_gyro"),
            3 => Some("ahrs"),
            4 => Some("full_nav"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "init" => Some(Self::INIT),
            "vert_gyro" => Some(Self::VERT_GYRO),
            "ahrs" => Some(Self::AHRS),
            "full_nav" => Some(Self::FULL_NAV),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterModeCv7 {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterModeCv7({} {})", self.0, name),
            None => write!(f, "FilterModeCv7({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterModeCv7 {
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
impl crate::json_read::FromJson for FilterModeCv7 {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter output valid flags. Valid flags of a filter output field: 0x0000 the values are invalid, 0x0001 they are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterOutputValidFlags(pub u16);

impl FilterOutputValidFlags {
    /// Mask of `valid` (bit 0).
    pub const VALID: u16 = 0x0001;

    /// The values of this field are valid. (bit 0)
    pub const fn valid(self) -> bool {
        self.0 & Self::VALID != 0
    }

    /// Sets or clears `valid` (bit 0).
    pub fn set_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::VALID;
        } else {
            self.0 &= !Self::VALID;
        }
    }
}

impl crate::wire::Wire for FilterOutputValidFlags {
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
impl crate::json_read::FromJson for FilterOutputValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Reference frame of user-specified positions and velocities.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterReferenceFrame(pub u8);

impl FilterReferenceFrame {
    /// WGS84 Earth-centered, Earth-fixed coordinates.
    pub const ECEF: Self = Self(1);
    /// WGS84 latitude, longitude and height above ellipsoid.
    pub const LLH: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("ecef"),
            2 => Some("llh"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "ecef" => Some(Self::ECEF),
            "llh" => Some(Self::LLH),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterReferenceFrame {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterReferenceFrame({} {})", self.0, name),
            None => write!(f, "FilterReferenceFrame({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterReferenceFrame {
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
impl crate::json_read::FromJson for FilterReferenceFrame {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter state (3DM-GX5-45). Operating state of the GX5-45 estimation filter, reported in Filter Status (0x82,0x10).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterStateGx5(pub u16);

impl FilterStateGx5 {
    /// Filter starting up.
    pub const STARTUP: Self = Self(0);
    /// Initializing; the status flags tell what is still missing.
    pub const INIT: Self = Self(1);
    /// Running, the solution is valid.
    pub const RUN_SOLUTION_VALID: Self = Self(2);
    /// Running, the solution has an error; the status flags tell which.
    pub const RUN_SOLUTION_ERROR: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("startup"),
            1 => Some("init"),
            2 => Some("run_solution_valid"),
            3 => Some("run_solution_error"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "startup" => Some(Self::STARTUP),
            "init" => Some(Self::INIT),
            "run_solution_valid" => Some(Self::RUN_SOLUTION_VALID),
            "run_solution_error" => Some(Self::RUN_SOLUTION_ERROR),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterStateGx5 {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterStateGx5({} {})", self.0, name),
            None => write!(f, "FilterStateGx5({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterStateGx5 {
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
impl crate::json_read::FromJson for FilterStateGx5 {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter status flags (3DM-CV7). CV7 (GQ7-family) filter status flags: the filter condition in bits 0-1 (1 stable, 2 converging, 3 unstable/recovering), estimate warnings in bits 2-10 and solution error flags in bits 12-15.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterStatusFlagsCv7(pub u16);

impl FilterStatusFlagsCv7 {
    /// Mask of `filter_condition` (bits 0..=1).
    pub const FILTER_CONDITION: u16 = 0x0003;
    /// Mask of `roll_pitch_warning` (bit 2).
    pub const ROLL_PITCH_WARNING: u16 = 0x0004;
    /// Mask of `heading_warning` (bit 3).
    pub const HEADING_WARNING: u16 = 0x0008;
    /// Mask of `position_warning` (bit 4).
    pub const POSITION_WARNING: u16 = 0x0010;
    /// Mask of `velocity_warning` (bit 5).
    pub const VELOCITY_WARNING: u16 = 0x0020;
    /// Mask of `imu_bias_warning` (bit 6).
    pub const IMU_BIAS_WARNING: u16 = 0x0040;
    /// Mask of `gnss_clk_warning` (bit 7).
    pub const GNSS_CLK_WARNING: u16 = 0x0080;
    /// Mask of `antenna_lever_arm_warning` (bit 8).
    pub const ANTENNA_LEVER_ARM_WARNING: u16 = 0x0100;
    /// Mask of `mounting_transform_warning` (bit 9).
    pub const MOUNTING_TRANSFORM_WARNING: u16 = 0x0200;
    /// Mask of `time_sync_warning` (bit 10).
    pub const TIME_SYNC_WARNING: u16 = 0x0400;
    /// Mask of `reserved` (bit 11).
    pub const RESERVED: u16 = 0x0800;
    /// Mask of `solution_error` (bits 12..=15).
    pub const SOLUTION_ERROR: u16 = 0xF000;

    /// Filter condition: 1 stable, 2 converging, 3 unstable/recovering. (bits 0..=1)
    pub const fn filter_condition(self) -> u16 {
        self.0 & Self::FILTER_CONDITION
    }

    /// Sets `filter_condition` (bits 0..=1); higher bits of `v` are ignored.
    pub fn set_filter_condition(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FILTER_CONDITION) | (v & Self::FILTER_CONDITION);
    }

    /// Low confidence in roll/pitch (e.g. sensor not aligned with the vehicle frame). (bit 2)
    pub const fn roll_pitch_warning(self) -> bool {
        self.0 & Self::ROLL_PITCH_WARNING != 0
    }

    /// Sets or clears `roll_pitch_warning` (bit 2).
    pub fn set_roll_pitch_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::ROLL_PITCH_WARNING;
        } else {
            self.0 &= !Self::ROLL_PITCH_WARNING;
        }
    }

    /// Low confidence in heading (heading source not valid). (bit 3)
    pub const fn heading_warning(self) -> bool {
        self.0 & Self::HEADING_WARNING != 0
    }

    /// Sets or clears `heading_warning` (bit 3).
    pub fn set_heading_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::HEADING_WARNING;
        } else {
            self.0 &= !Self::HEADING_WARNING;
        }
    }

    /// Low confidence in position. (bit 4)
    pub const fn position_warning(self) -> bool {
        self.0 & Self::POSITION_WARNING != 0
    }

    /// Sets or clears `position_warning` (bit 4).
    pub fn set_position_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::POSITION_WARNING;
        } else {
            self.0 &= !Self::POSITION_WARNING;
        }
    }

    /// Low confidence in velocity. (bit 5)
    pub const fn velocity_warning(self) -> bool {
        self.0 & Self::VELOCITY_WARNING != 0
    }

    /// Sets or clears `velocity_warning` (bit 5).
    pub fn set_velocity_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::VELOCITY_WARNING;
        } else {
            self.0 &= !Self::VELOCITY_WARNING;
        }
    }

    /// IMU bias estimate warning (gyro bias high). (bit 6)
    pub const fn imu_bias_warning(self) -> bool {
        self.0 & Self::IMU_BIAS_WARNING != 0
    }

    /// Sets or clears `imu_bias_warning` (bit 6).
    pub fn set_imu_bias_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_BIAS_WARNING;
        } else {
            self.0 &= !Self::IMU_BIAS_WARNING;
        }
    }

    /// GNSS clock warning (affects the filter timestamp). (bit 7)
    pub const fn gnss_clk_warning(self) -> bool {
        self.0 & Self::GNSS_CLK_WARNING != 0
    }

    /// Sets or clears `gnss_clk_warning` (bit 7).
    pub fn set_gnss_clk_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_CLK_WARNING;
        } else {
            self.0 &= !Self::GNSS_CLK_WARNING;
        }
    }

    /// Antenna lever arm offsets are likely incorrect. (bit 8)
    pub const fn antenna_lever_arm_warning(self) -> bool {
        self.0 & Self::ANTENNA_LEVER_ARM_WARNING != 0
    }

    /// Sets or clears `antenna_lever_arm_warning` (bit 8).
    pub fn set_antenna_lever_arm_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::ANTENNA_LEVER_ARM_WARNING;
        } else {
            self.0 &= !Self::ANTENNA_LEVER_ARM_WARNING;
        }
    }

    /// Mounting transform is likely incorrect. (bit 9)
    pub const fn mounting_transform_warning(self) -> bool {
        self.0 & Self::MOUNTING_TRANSFORM_WARNING != 0
    }

    /// Sets or clears `mounting_transform_warning` (bit 9).
    pub fn set_mounting_transform_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::MOUNTING_TRANSFORM_WARNING;
        } else {
            self.0 &= !Self::MOUNTING_TRANSFORM_WARNING;
        }
    }

    /// No time synchronization (PPS) pulse detected, or external heading timestamp too old. (bit 10)
    pub const fn time_sync_warning(self) -> bool {
        self.0 & Self::TIME_SYNC_WARNING != 0
    }

    /// Sets or clears `time_sync_warning` (bit 10).
    pub fn set_time_sync_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIME_SYNC_WARNING;
        } else {
            self.0 &= !Self::TIME_SYNC_WARNING;
        }
    }

    /// Not listed. Reserved. (bit 11)
    pub const fn reserved(self) -> bool {
        self.0 & Self::RESERVED != 0
    }

    /// Sets or clears `reserved` (bit 11).
    pub fn set_reserved(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED;
        } else {
            self.0 &= !Self::RESERVED;
        }
    }

    /// Filter computation error flags (NaN in the solution); if any is set, all filter outputs are invalid. (bits 12..=15)
    pub const fn solution_error(self) -> u16 {
        (self.0 & Self::SOLUTION_ERROR) >> 12
    }

    /// Sets `solution_error` (bits 12..=15); higher bits of `v` are ignored.
    pub fn set_solution_error(&mut self, v: u16) {
        self.0 = (self.0 & !Self::SOLUTION_ERROR) | ((v << 12) & Self::SOLUTION_ERROR);
    }
}

impl crate::wire::Wire for FilterStatusFlagsCv7 {
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
impl crate::json_read::FromJson for FilterStatusFlagsCv7 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter status flags (3DM-GX5-45). GX5-45 filter status flags. Bits 12 and 13 mean different things depending on the filter state: in the initialization state they say what is not initialized, while running they are estimate warnings.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FilterStatusFlagsGx5(pub u16);

impl FilterStatusFlagsGx5 {
    /// Mask of `run_imu_unavailable` (bit 0).
    pub const RUN_IMU_UNAVAILABLE: u16 = 0x0001;
    /// Mask of `run_gps_unavailable` (bit 1).
    pub const RUN_GPS_UNAVAILABLE: u16 = 0x0002;
    /// Mask of `reserved` (bit 2).
    pub const RESERVED: u16 = 0x0004;
    /// Mask of `run_matrix_singularity` (bit 3).
    pub const RUN_MATRIX_SINGULARITY: u16 = 0x0008;
    /// Mask of `run_position_covariance_warning` (bit 4).
    pub const RUN_POSITION_COVARIANCE_WARNING: u16 = 0x0010;
    /// Mask of `run_velocity_covariance_warning` (bit 5).
    pub const RUN_VELOCITY_COVARIANCE_WARNING: u16 = 0x0020;
    /// Mask of `run_attitude_covariance_warning` (bit 6).
    pub const RUN_ATTITUDE_COVARIANCE_WARNING: u16 = 0x0040;
    /// Mask of `run_nan_in_solution_warning` (bit 7).
    pub const RUN_NAN_IN_SOLUTION_WARNING: u16 = 0x0080;
    /// Mask of `run_gyro_bias_est_high_warning` (bit 8).
    pub const RUN_GYRO_BIAS_EST_HIGH_WARNING: u16 = 0x0100;
    /// Mask of `run_accel_bias_est_high_warning` (bit 9).
    pub const RUN_ACCEL_BIAS_EST_HIGH_WARNING: u16 = 0x0200;
    /// Mask of `run_gyro_scale_factor_est_high_warning` (bit 10).
    pub const RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING: u16 = 0x0400;
    /// Mask of `run_accel_scale_factor_est_high_warning` (bit 11).
    pub const RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING: u16 = 0x0800;
    /// Mask of `run_mag_bias_est_high_warning` (bit 12).
    pub const RUN_MAG_BIAS_EST_HIGH_WARNING: u16 = 0x1000;
    /// Mask of `run_ant_offset_correction_est_high_warning` (bit 13).
    pub const RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING: u16 = 0x2000;
    /// Mask of `run_mag_hard_iron_est_high_warning` (bit 14).
    pub const RUN_MAG_HARD_IRON_EST_HIGH_WARNING: u16 = 0x4000;
    /// Mask of `run_mag_soft_iron_est_high_warning` (bit 15).
    pub const RUN_MAG_SOFT_IRON_EST_HIGH_WARNING: u16 = 0x8000;
    /// Mask of `init_no_attitude` (bit 12).
    pub const INIT_NO_ATTITUDE: u16 = 0x1000;
    /// Mask of `init_no_position_velocity` (bit 13).
    pub const INIT_NO_POSITION_VELOCITY: u16 = 0x2000;

    /// Running: IMU unavailable. (bit 0)
    pub const fn run_imu_unavailable(self) -> bool {
        self.0 & Self::RUN_IMU_UNAVAILABLE != 0
    }

    /// Sets or clears `run_imu_unavailable` (bit 0).
    pub fn set_run_imu_unavailable(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_IMU_UNAVAILABLE;
        } else {
            self.0 &= !Self::RUN_IMU_UNAVAILABLE;
        }
    }

    /// Running: GNSS unavailable. (bit 1)
    pub const fn run_gps_unavailable(self) -> bool {
        self.0 & Self::RUN_GPS_UNAVAILABLE != 0
    }

    /// Sets or clears `run_gps_unavailable` (bit 1).
    pub fn set_run_gps_unavailable(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_GPS_UNAVAILABLE;
        } else {
            self.0 &= !Self::RUN_GPS_UNAVAILABLE;
        }
    }

    /// Not listed (0x0004). Reserved. (bit 2)
    pub const fn reserved(self) -> bool {
        self.0 & Self::RESERVED != 0
    }

    /// Sets or clears `reserved` (bit 2).
    pub fn set_reserved(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED;
        } else {
            self.0 &= !Self::RESERVED;
        }
    }

    /// Running: matrix singularity in the calculation. (bit 3)
    pub const fn run_matrix_singularity(self) -> bool {
        self.0 & Self::RUN_MATRIX_SINGULARITY != 0
    }

    /// Sets or clears `run_matrix_singularity` (bit 3).
    pub fn set_run_matrix_singularity(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_MATRIX_SINGULARITY;
        } else {
            self.0 &= !Self::RUN_MATRIX_SINGULARITY;
        }
    }

    /// Running: position covariance high (some axis beyond normal limits). (bit 4)
    pub const fn run_position_covariance_warning(self) -> bool {
        self.0 & Self::RUN_POSITION_COVARIANCE_WARNING != 0
    }

    /// Sets or clears `run_position_covariance_warning` (bit 4).
    pub fn set_run_position_covariance_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_POSITION_COVARIANCE_WARNING;
        } else {
            self.0 &= !Self::RUN_POSITION_COVARIANCE_WARNING;
        }
    }

    /// Running: velocity covariance high (some axis beyond normal limits). (bit 5)
    pub const fn run_velocity_covariance_warning(self) -> bool {
        self.0 & Self::RUN_VELOCITY_COVARIANCE_WARNING != 0
    }

    /// Sets or clears `run_velocity_covariance_warning` (bit 5).
    pub fn set_run_velocity_covariance_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_VELOCITY_COVARIANCE_WARNING;
        } else {
            self.0 &= !Self::RUN_VELOCITY_COVARIANCE_WARNING;
        }
    }

    /// Running: attitude covariance high (some axis beyond normal limits). (bit 6)
    pub const fn run_attitude_covariance_warning(self) -> bool {
        self.0 & Self::RUN_ATTITUDE_COVARIANCE_WARNING != 0
    }

    /// Sets or clears `run_attitude_covariance_warning` (bit 6).
    pub fn set_run_attitude_covariance_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_ATTITUDE_COVARIANCE_WARNING;
        } else {
            self.0 &= !Self::RUN_ATTITUDE_COVARIANCE_WARNING;
        }
    }

    /// Running: NaN in the solution. (bit 7)
    pub const fn run_nan_in_solution_warning(self) -> bool {
        self.0 & Self::RUN_NAN_IN_SOLUTION_WARNING != 0
    }

    /// Sets or clears `run_nan_in_solution_warning` (bit 7).
    pub fn set_run_nan_in_solution_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_NAN_IN_SOLUTION_WARNING;
        } else {
            self.0 &= !Self::RUN_NAN_IN_SOLUTION_WARNING;
        }
    }

    /// Running: gyro bias estimate high. (bit 8)
    pub const fn run_gyro_bias_est_high_warning(self) -> bool {
        self.0 & Self::RUN_GYRO_BIAS_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_gyro_bias_est_high_warning` (bit 8).
    pub fn set_run_gyro_bias_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_GYRO_BIAS_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_GYRO_BIAS_EST_HIGH_WARNING;
        }
    }

    /// Running: accel bias estimate high. (bit 9)
    pub const fn run_accel_bias_est_high_warning(self) -> bool {
        self.0 & Self::RUN_ACCEL_BIAS_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_accel_bias_est_high_warning` (bit 9).
    pub fn set_run_accel_bias_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_ACCEL_BIAS_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_ACCEL_BIAS_EST_HIGH_WARNING;
        }
    }

    /// Running: gyro scale factor estimate high. (bit 10)
    pub const fn run_gyro_scale_factor_est_high_warning(self) -> bool {
        self.0 & Self::RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_gyro_scale_factor_est_high_warning` (bit 10).
    pub fn set_run_gyro_scale_factor_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING;
        }
    }

    /// Running: accel scale factor estimate high. (bit 11)
    pub const fn run_accel_scale_factor_est_high_warning(self) -> bool {
        self.0 & Self::RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_accel_scale_factor_est_high_warning` (bit 11).
    pub fn set_run_accel_scale_factor_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING;
        }
    }

    /// Running: magnetometer bias estimate high. (bit 12)
    pub const fn run_mag_bias_est_high_warning(self) -> bool {
        self.0 & Self::RUN_MAG_BIAS_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_mag_bias_est_high_warning` (bit 12).
    pub fn set_run_mag_bias_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_MAG_BIAS_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_MAG_BIAS_EST_HIGH_WARNING;
        }
    }

    /// Running: GNSS antenna offset correction estimate high. (bit 13)
    pub const fn run_ant_offset_correction_est_high_warning(self) -> bool {
        self.0 & Self::RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_ant_offset_correction_est_high_warning` (bit 13).
    pub fn set_run_ant_offset_correction_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING;
        }
    }

    /// Running: hard iron offset estimate high. (bit 14)
    pub const fn run_mag_hard_iron_est_high_warning(self) -> bool {
        self.0 & Self::RUN_MAG_HARD_IRON_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_mag_hard_iron_est_high_warning` (bit 14).
    pub fn set_run_mag_hard_iron_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_MAG_HARD_IRON_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_MAG_HARD_IRON_EST_HIGH_WARNING;
        }
    }

    /// Running: soft iron correction estimate high. (bit 15)
    pub const fn run_mag_soft_iron_est_high_warning(self) -> bool {
        self.0 & Self::RUN_MAG_SOFT_IRON_EST_HIGH_WARNING != 0
    }

    /// Sets or clears `run_mag_soft_iron_est_high_warning` (bit 15).
    pub fn set_run_mag_soft_iron_est_high_warning(&mut self, v: bool) {
        if v {
            self.0 |= Self::RUN_MAG_SOFT_IRON_EST_HIGH_WARNING;
        } else {
            self.0 &= !Self::RUN_MAG_SOFT_IRON_EST_HIGH_WARNING;
        }
    }

    /// Initialization: attitude not initialized (same bit as run_mag_bias_est_high_warning). (bit 12)
    pub const fn init_no_attitude(self) -> bool {
        self.0 & Self::INIT_NO_ATTITUDE != 0
    }

    /// Sets or clears `init_no_attitude` (bit 12).
    pub fn set_init_no_attitude(&mut self, v: bool) {
        if v {
            self.0 |= Self::INIT_NO_ATTITUDE;
        } else {
            self.0 &= !Self::INIT_NO_ATTITUDE;
        }
    }

    /// Initialization: position and velocity not initialized (same bit as run_ant_offset_correction_est_high_warning). (bit 13)
    pub const fn init_no_position_velocity(self) -> bool {
        self.0 & Self::INIT_NO_POSITION_VELOCITY != 0
    }

    /// Sets or clears `init_no_position_velocity` (bit 13).
    pub fn set_init_no_position_velocity(&mut self, v: bool) {
        if v {
            self.0 |= Self::INIT_NO_POSITION_VELOCITY;
        } else {
            self.0 &= !Self::INIT_NO_POSITION_VELOCITY;
        }
    }
}

impl crate::wire::Wire for FilterStatusFlagsGx5 {
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
impl crate::json_read::FromJson for FilterStatusFlagsGx5 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Function selector. First parameter of settings commands; chooses what the command does. Only a read returns a response field (with the ack); parameters not needed for a function may be left out, or sent as placeholders.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FunctionSelector(pub u8);

impl FunctionSelector {
    /// Apply new setting.
    pub const WRITE: Self = Self(1);
    /// Read back the current setting (the only function that returns response data).
    pub const READ: Self = Self(2);
    /// Save the current setting to non-volatile memory as the startup setting.
    pub const SAVE: Self = Self(3);
    /// Load the saved startup setting from non-volatile memory.
    pub const LOAD: Self = Self(4);
    /// Reset to the factory default.
    pub const DEFAULT: Self = Self(5);
    /// Apply new setting with no ACK/NACK reply (GX5-45 only). Devices: gx5_45.
    pub const WRITE_NO_ACK: Self = Self(6);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("write"),
            2 => Some("read"),
            3 => Some("save"),
            4 => Some("load"),
            5 => Some("default"),
            6 => Some("write_no_ack"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "write" => Some(Self::WRITE),
            "read" => Some(Self::READ),
            "save" => Some(Self::SAVE),
            "load" => Some(Self::LOAD),
            "default" => Some(Self::DEFAULT),
            "write_no_ack" => Some(Self::WRITE_NO_ACK),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FunctionSelector {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FunctionSelector({} {})", self.0, name),
            None => write!(f, "FunctionSelector({})", self.0),
        }
    }
}

impl crate::wire::Wire for FunctionSelector {
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
impl crate::json_read::FromJson for FunctionSelector {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS antenna power. Whether the receiver powers the antenna.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssAntennaPower(pub u8);

impl GnssAntennaPower {
    /// Antenna power off.
    pub const OFF: Self = Self(0);
    /// Antenna power on.
    pub const ON: Self = Self(1);
    /// Power state unknown.
    pub const UNKNOWN: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("off"),
            1 => Some("on"),
            2 => Some("unknown"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "off" => Some(Self::OFF),
            "on" => Some(Self::ON),
            "unknown" => Some(Self::UNKNOWN),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssAntennaPower {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssAntennaPower({} {})", self.0, name),
            None => write!(f, "GnssAntennaPower({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssAntennaPower {
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
impl crate::json_read::FromJson for GnssAntennaPower {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS antenna state. State of the GNSS antenna connection. There is no value 0.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssAntennaState(pub u8);

impl GnssAntennaState {
    /// Antenna initialising.
    pub const INIT: Self = Self(1);
    /// Antenna short circuit.
    pub const SHORT: Self = Self(2);
    /// Antenna open circuit (not connected).
    pub const OPEN: Self = Self(3);
    /// Antenna good.
    pub const GOOD: Self = Self(4);
    /// State unknown.
    pub const UNKNOWN: Self = Self(5);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("init"),
            2 => Some("short"),
            3 => Some("open"),
            4 => Some("good"),
            5 => Some("unknown"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "init" => Some(Self::INIT),
            "short" => Some(Self::SHORT),
            "open" => Some(Self::OPEN),
            "good" => Some(Self::GOOD),
            "unknown" => Some(Self::UNKNOWN),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssAntennaState {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssAntennaState({} {})", self.0, name),
            None => write!(f, "GnssAntennaState({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssAntennaState {
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
impl crate::json_read::FromJson for GnssAntennaState {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Base station indicators. Indicator bits of the base station, as reported in RTCM message 1005/1006.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssBaseStationIndicators(pub u16);

impl GnssBaseStationIndicators {
    /// Mask of `gps` (bit 0).
    pub const GPS: u16 = 0x0001;
    /// Mask of `glonass` (bit 1).
    pub const GLONASS: u16 = 0x0002;
    /// Mask of `galileo` (bit 2).
    pub const GALILEO: u16 = 0x0004;
    /// Mask of `beidou` (bit 3).
    pub const BEIDOU: u16 = 0x0008;
    /// Mask of `ref_station` (bit 4).
    pub const REF_STATION: u16 = 0x0010;
    /// Mask of `single_receiver` (bit 5).
    pub const SINGLE_RECEIVER: u16 = 0x0020;
    /// Mask of `quarter_cycle_bit1` (bit 6).
    pub const QUARTER_CYCLE_BIT1: u16 = 0x0040;
    /// Mask of `quarter_cycle_bit2` (bit 7).
    pub const QUARTER_CYCLE_BIT2: u16 = 0x0080;
    /// Mask of `quarter_cycle_bits` (bits 6..=7).
    pub const QUARTER_CYCLE_BITS: u16 = 0x00C0;
    /// Mask of `reserved` (bits 8..=15).
    pub const RESERVED: u16 = 0xFF00;

    /// GPS indicator. (bit 0)
    pub const fn gps(self) -> bool {
        self.0 & Self::GPS != 0
    }

    /// Sets or clears `gps` (bit 0).
    pub fn set_gps(&mut self, v: bool) {
        if v {
            self.0 |= Self::GPS;
        } else {
            self.0 &= !Self::GPS;
        }
    }

    /// GLONASS indicator. (bit 1)
    pub const fn glonass(self) -> bool {
        self.0 & Self::GLONASS != 0
    }

    /// Sets or clears `glonass` (bit 1).
    pub fn set_glonass(&mut self, v: bool) {
        if v {
            self.0 |= Self::GLONASS;
        } else {
            self.0 &= !Self::GLONASS;
        }
    }

    /// Galileo indicator. (bit 2)
    pub const fn galileo(self) -> bool {
        self.0 & Self::GALILEO != 0
    }

    /// Sets or clears `galileo` (bit 2).
    pub fn set_galileo(&mut self, v: bool) {
        if v {
            self.0 |= Self::GALILEO;
        } else {
            self.0 &= !Self::GALILEO;
        }
    }

    /// BeiDou indicator. (bit 3)
    pub const fn beidou(self) -> bool {
        self.0 & Self::BEIDOU != 0
    }

    /// Sets or clears `beidou` (bit 3).
    pub fn set_beidou(&mut self, v: bool) {
        if v {
            self.0 |= Self::BEIDOU;
        } else {
            self.0 &= !Self::BEIDOU;
        }
    }

    /// Reference station indicator. (bit 4)
    pub const fn ref_station(self) -> bool {
        self.0 & Self::REF_STATION != 0
    }

    /// Sets or clears `ref_station` (bit 4).
    pub fn set_ref_station(&mut self, v: bool) {
        if v {
            self.0 |= Self::REF_STATION;
        } else {
            self.0 &= !Self::REF_STATION;
        }
    }

    /// Single receiver oscillator indicator. (bit 5)
    pub const fn single_receiver(self) -> bool {
        self.0 & Self::SINGLE_RECEIVER != 0
    }

    /// Sets or clears `single_receiver` (bit 5).
    pub fn set_single_receiver(&mut self, v: bool) {
        if v {
            self.0 |= Self::SINGLE_RECEIVER;
        } else {
            self.0 &= !Self::SINGLE_RECEIVER;
        }
    }

    /// Quarter cycle indicator, first bit. (bit 6)
    pub const fn quarter_cycle_bit1(self) -> bool {
        self.0 & Self::QUARTER_CYCLE_BIT1 != 0
    }

    /// Sets or clears `quarter_cycle_bit1` (bit 6).
    pub fn set_quarter_cycle_bit1(&mut self, v: bool) {
        if v {
            self.0 |= Self::QUARTER_CYCLE_BIT1;
        } else {
            self.0 &= !Self::QUARTER_CYCLE_BIT1;
        }
    }

    /// Quarter cycle indicator, second bit. (bit 7)
    pub const fn quarter_cycle_bit2(self) -> bool {
        self.0 & Self::QUARTER_CYCLE_BIT2 != 0
    }

    /// Sets or clears `quarter_cycle_bit2` (bit 7).
    pub fn set_quarter_cycle_bit2(&mut self, v: bool) {
        if v {
            self.0 |= Self::QUARTER_CYCLE_BIT2;
        } else {
            self.0 &= !Self::QUARTER_CYCLE_BIT2;
        }
    }

    /// Quarter cycle indicator (both bits). (bits 6..=7)
    pub const fn quarter_cycle_bits(self) -> u16 {
        (self.0 & Self::QUARTER_CYCLE_BITS) >> 6
    }

    /// Sets `quarter_cycle_bits` (bits 6..=7); higher bits of `v` are ignored.
    pub fn set_quarter_cycle_bits(&mut self, v: u16) {
        self.0 = (self.0 & !Self::QUARTER_CYCLE_BITS) | ((v << 6) & Self::QUARTER_CYCLE_BITS);
    }

    /// Not named by the manual. Reserved. (bits 8..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 8
    }

    /// Sets `reserved` (bits 8..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 8) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssBaseStationIndicators {
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
impl crate::json_read::FromJson for GnssBaseStationIndicators {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Base station information valid flags. Which parameters of the base station information field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssBaseStationInfoValidFlags(pub u16);

impl GnssBaseStationInfoValidFlags {
    /// Mask of `tow` (bit 0).
    pub const TOW: u16 = 0x0001;
    /// Mask of `week_number` (bit 1).
    pub const WEEK_NUMBER: u16 = 0x0002;
    /// Mask of `ecef_position` (bit 2).
    pub const ECEF_POSITION: u16 = 0x0004;
    /// Mask of `height` (bit 3).
    pub const HEIGHT: u16 = 0x0008;
    /// Mask of `station_id` (bit 4).
    pub const STATION_ID: u16 = 0x0010;
    /// Mask of `indicators` (bit 5).
    pub const INDICATORS: u16 = 0x0020;
    /// Mask of `flags` (bits 0..=5).
    pub const FLAGS: u16 = 0x003F;
    /// Mask of `reserved` (bits 6..=15).
    pub const RESERVED: u16 = 0xFFC0;

    /// Time of week valid. (bit 0)
    pub const fn tow(self) -> bool {
        self.0 & Self::TOW != 0
    }

    /// Sets or clears `tow` (bit 0).
    pub fn set_tow(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW;
        } else {
            self.0 &= !Self::TOW;
        }
    }

    /// Week number valid. (bit 1)
    pub const fn week_number(self) -> bool {
        self.0 & Self::WEEK_NUMBER != 0
    }

    /// Sets or clears `week_number` (bit 1).
    pub fn set_week_number(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER;
        } else {
            self.0 &= !Self::WEEK_NUMBER;
        }
    }

    /// ECEF position valid. (bit 2)
    pub const fn ecef_position(self) -> bool {
        self.0 & Self::ECEF_POSITION != 0
    }

    /// Sets or clears `ecef_position` (bit 2).
    pub fn set_ecef_position(&mut self, v: bool) {
        if v {
            self.0 |= Self::ECEF_POSITION;
        } else {
            self.0 &= !Self::ECEF_POSITION;
        }
    }

    /// Antenna height valid. (bit 3)
    pub const fn height(self) -> bool {
        self.0 & Self::HEIGHT != 0
    }

    /// Sets or clears `height` (bit 3).
    pub fn set_height(&mut self, v: bool) {
        if v {
            self.0 |= Self::HEIGHT;
        } else {
            self.0 &= !Self::HEIGHT;
        }
    }

    /// Station id valid. (bit 4)
    pub const fn station_id(self) -> bool {
        self.0 & Self::STATION_ID != 0
    }

    /// Sets or clears `station_id` (bit 4).
    pub fn set_station_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::STATION_ID;
        } else {
            self.0 &= !Self::STATION_ID;
        }
    }

    /// Indicators valid. (bit 5)
    pub const fn indicators(self) -> bool {
        self.0 & Self::INDICATORS != 0
    }

    /// Sets or clears `indicators` (bit 5).
    pub fn set_indicators(&mut self, v: bool) {
        if v {
            self.0 |= Self::INDICATORS;
        } else {
            self.0 &= !Self::INDICATORS;
        }
    }

    /// All flags. (bits 0..=5)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=5); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manual. Reserved. (bits 6..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 6
    }

    /// Sets `reserved` (bits 6..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 6) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssBaseStationInfoValidFlags {
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
impl crate::json_read::FromJson for GnssBaseStationInfoValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// BeiDou signals enabled.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssBeidouSignals(pub u8);

impl GnssBeidouSignals {
    /// Mask of `b1` (bit 0).
    pub const B1: u8 = 0x01;
    /// Mask of `b2` (bit 1).
    pub const B2: u8 = 0x02;
    /// Mask of `b2a` (bit 2).
    pub const B2A: u8 = 0x04;

    /// Enable B1. (bit 0)
    pub const fn b1(self) -> bool {
        self.0 & Self::B1 != 0
    }

    /// Sets or clears `b1` (bit 0).
    pub fn set_b1(&mut self, v: bool) {
        if v {
            self.0 |= Self::B1;
        } else {
            self.0 &= !Self::B1;
        }
    }

    /// Enable B2. (bit 1)
    pub const fn b2(self) -> bool {
        self.0 & Self::B2 != 0
    }

    /// Sets or clears `b2` (bit 1).
    pub fn set_b2(&mut self, v: bool) {
        if v {
            self.0 |= Self::B2;
        } else {
            self.0 &= !Self::B2;
        }
    }

    /// Enable B2A. (bit 2)
    pub const fn b2a(self) -> bool {
        self.0 & Self::B2A != 0
    }

    /// Sets or clears `b2a` (bit 2).
    pub fn set_b2a(&mut self, v: bool) {
        if v {
            self.0 |= Self::B2A;
        } else {
            self.0 &= !Self::B2A;
        }
    }
}

impl crate::wire::Wire for GnssBeidouSignals {
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
impl crate::json_read::FromJson for GnssBeidouSignals {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS clock information 2 valid flags. Which receiver clock parameters are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssClockInfo2ValidFlags(pub u16);

impl GnssClockInfo2ValidFlags {
    /// Mask of `bias` (bit 0).
    pub const BIAS: u16 = 0x0001;
    /// Mask of `drift` (bit 1).
    pub const DRIFT: u16 = 0x0002;
    /// Mask of `bias_accuracy` (bit 2).
    pub const BIAS_ACCURACY: u16 = 0x0004;
    /// Mask of `drift_accuracy` (bit 3).
    pub const DRIFT_ACCURACY: u16 = 0x0008;
    /// Mask of `flags` (bits 0..=3).
    pub const FLAGS: u16 = 0x000F;
    /// Mask of `reserved` (bits 4..=15).
    pub const RESERVED: u16 = 0xFFF0;

    /// Clock bias valid. (bit 0)
    pub const fn bias(self) -> bool {
        self.0 & Self::BIAS != 0
    }

    /// Sets or clears `bias` (bit 0).
    pub fn set_bias(&mut self, v: bool) {
        if v {
            self.0 |= Self::BIAS;
        } else {
            self.0 &= !Self::BIAS;
        }
    }

    /// Clock drift valid. (bit 1)
    pub const fn drift(self) -> bool {
        self.0 & Self::DRIFT != 0
    }

    /// Sets or clears `drift` (bit 1).
    pub fn set_drift(&mut self, v: bool) {
        if v {
            self.0 |= Self::DRIFT;
        } else {
            self.0 &= !Self::DRIFT;
        }
    }

    /// Bias accuracy estimate valid. (bit 2)
    pub const fn bias_accuracy(self) -> bool {
        self.0 & Self::BIAS_ACCURACY != 0
    }

    /// Sets or clears `bias_accuracy` (bit 2).
    pub fn set_bias_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::BIAS_ACCURACY;
        } else {
            self.0 &= !Self::BIAS_ACCURACY;
        }
    }

    /// Drift accuracy estimate valid. (bit 3)
    pub const fn drift_accuracy(self) -> bool {
        self.0 & Self::DRIFT_ACCURACY != 0
    }

    /// Sets or clears `drift_accuracy` (bit 3).
    pub fn set_drift_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::DRIFT_ACCURACY;
        } else {
            self.0 &= !Self::DRIFT_ACCURACY;
        }
    }

    /// All flags. (bits 0..=3)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=3); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manual. Reserved. (bits 4..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 4
    }

    /// Sets `reserved` (bits 4..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 4) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssClockInfo2ValidFlags {
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
impl crate::json_read::FromJson for GnssClockInfo2ValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS clock information valid flags. Which clock parameters are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssClockInfoValidFlags(pub u16);

impl GnssClockInfoValidFlags {
    /// Mask of `bias` (bit 0).
    pub const BIAS: u16 = 0x0001;
    /// Mask of `drift` (bit 1).
    pub const DRIFT: u16 = 0x0002;
    /// Mask of `accuracy_estimate` (bit 2).
    pub const ACCURACY_ESTIMATE: u16 = 0x0004;
    /// Mask of `reserved` (bits 3..=15).
    pub const RESERVED: u16 = 0xFFF8;

    /// Clock bias valid. (bit 0)
    pub const fn bias(self) -> bool {
        self.0 & Self::BIAS != 0
    }

    /// Sets or clears `bias` (bit 0).
    pub fn set_bias(&mut self, v: bool) {
        if v {
            self.0 |= Self::BIAS;
        } else {
            self.0 &= !Self::BIAS;
        }
    }

    /// Clock drift valid. (bit 1)
    pub const fn drift(self) -> bool {
        self.0 & Self::DRIFT != 0
    }

    /// Sets or clears `drift` (bit 1).
    pub fn set_drift(&mut self, v: bool) {
        if v {
            self.0 |= Self::DRIFT;
        } else {
            self.0 &= !Self::DRIFT;
        }
    }

    /// Accuracy estimate valid. (bit 2)
    pub const fn accuracy_estimate(self) -> bool {
        self.0 & Self::ACCURACY_ESTIMATE != 0
    }

    /// Sets or clears `accuracy_estimate` (bit 2).
    pub fn set_accuracy_estimate(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCURACY_ESTIMATE;
        } else {
            self.0 &= !Self::ACCURACY_ESTIMATE;
        }
    }

    /// Not named by the manual. Reserved. (bits 3..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 3
    }

    /// Sets `reserved` (bits 3..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 3) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssClockInfoValidFlags {
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
impl crate::json_read::FromJson for GnssClockInfoValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS constellation (CV7 GNSS data).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssConstellationId(pub u8);

impl GnssConstellationId {
    /// Constellation unknown or not given.
    pub const UNKNOWN: Self = Self(0);
    /// GPS.
    pub const GPS: Self = Self(1);
    /// GLONASS.
    pub const GLONASS: Self = Self(2);
    /// Galileo.
    pub const GALILEO: Self = Self(3);
    /// BeiDou.
    pub const BEIDOU: Self = Self(4);
    /// SBAS.
    pub const SBAS: Self = Self(5);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unknown"),
            1 => Some("gps"),
            2 => Some("glonass"),
            3 => Some("galileo"),
            4 => Some("beidou"),
            5 => Some("sbas"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unknown" => Some(Self::UNKNOWN),
            "gps" => Some(Self::GPS),
            "glonass" => Some(Self::GLONASS),
            "galileo" => Some(Self::GALILEO),
            "beidou" => Some(Self::BEIDOU),
            "sbas" => Some(Self::SBAS),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssConstellationId {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssConstellationId({} {})", self.0, name),
            None => write!(f, "GnssConstellationId({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssConstellationId {
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
impl crate::json_read::FromJson for GnssConstellationId {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// DGNSS base station status. Health of the DGNSS reference station as its UDRE (user differential range error) scale factor.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssDgnssBaseStationStatus(pub i16);

impl GnssDgnssBaseStationStatus {
    /// UDRE scale factor 1.0.
    pub const UDRE_SCALE_1_0: Self = Self(0);
    /// UDRE scale factor 0.75.
    pub const UDRE_SCALE_0_75: Self = Self(1);
    /// UDRE scale factor 0.5.
    pub const UDRE_SCALE_0_5: Self = Self(2);
    /// UDRE scale factor 0.3.
    pub const UDRE_SCALE_0_3: Self = Self(3);
    /// UDRE scale factor 0.2.
    pub const UDRE_SCALE_0_2: Self = Self(4);
    /// UDRE scale factor 0.1.
    pub const UDRE_SCALE_0_1: Self = Self(5);
    /// Reference station transmission not monitored.
    pub const TRANSMISSION_NOT_MONITORED: Self = Self(6);
    /// Reference station not working.
    pub const STATION_NOT_WORKING: Self = Self(7);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("udre_scale_1_0"),
            1 => Some("udre_scale_0_75"),
            2 => Some("udre_scale_0_5"),
            3 => Some("udre_scale_0_3"),
            4 => Some("udre_scale_0_2"),
            5 => Some("udre_scale_0_1"),
            6 => Some("transmission_not_monitored"),
            7 => Some("station_not_working"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "udre_scale_1_0" => Some(Self::UDRE_SCALE_1_0),
            "udre_scale_0_75" => Some(Self::UDRE_SCALE_0_75),
            "udre_scale_0_5" => Some(Self::UDRE_SCALE_0_5),
            "udre_scale_0_3" => Some(Self::UDRE_SCALE_0_3),
            "udre_scale_0_2" => Some(Self::UDRE_SCALE_0_2),
            "udre_scale_0_1" => Some(Self::UDRE_SCALE_0_1),
            "transmission_not_monitored" => Some(Self::TRANSMISSION_NOT_MONITORED),
            "station_not_working" => Some(Self::STATION_NOT_WORKING),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssDgnssBaseStationStatus {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssDgnssBaseStationStatus({} {})", self.0, name),
            None => write!(f, "GnssDgnssBaseStationStatus({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssDgnssBaseStationStatus {
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
impl crate::json_read::FromJson for GnssDgnssBaseStationStatus {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <i16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// DGNSS channel status valid flags. Which parameters of a DGNSS channel status entry are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssDgnssChannelStatusValidFlags(pub u16);

impl GnssDgnssChannelStatusValidFlags {
    /// Mask of `sv_id` (bit 0).
    pub const SV_ID: u16 = 0x0001;
    /// Mask of `age` (bit 1).
    pub const AGE: u16 = 0x0002;
    /// Mask of `pseudorange_correction` (bit 2).
    pub const PSEUDORANGE_CORRECTION: u16 = 0x0004;
    /// Mask of `pseudorange_rate_correction` (bit 3).
    pub const PSEUDORANGE_RATE_CORRECTION: u16 = 0x0008;
    /// Mask of `reserved` (bits 4..=15).
    pub const RESERVED: u16 = 0xFFF0;

    /// Space vehicle id valid. (bit 0)
    pub const fn sv_id(self) -> bool {
        self.0 & Self::SV_ID != 0
    }

    /// Sets or clears `sv_id` (bit 0).
    pub fn set_sv_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::SV_ID;
        } else {
            self.0 &= !Self::SV_ID;
        }
    }

    /// Correction age valid. (bit 1)
    pub const fn age(self) -> bool {
        self.0 & Self::AGE != 0
    }

    /// Sets or clears `age` (bit 1).
    pub fn set_age(&mut self, v: bool) {
        if v {
            self.0 |= Self::AGE;
        } else {
            self.0 &= !Self::AGE;
        }
    }

    /// Pseudorange correction valid. (bit 2)
    pub const fn pseudorange_correction(self) -> bool {
        self.0 & Self::PSEUDORANGE_CORRECTION != 0
    }

    /// Sets or clears `pseudorange_correction` (bit 2).
    pub fn set_pseudorange_correction(&mut self, v: bool) {
        if v {
            self.0 |= Self::PSEUDORANGE_CORRECTION;
        } else {
            self.0 &= !Self::PSEUDORANGE_CORRECTION;
        }
    }

    /// Pseudorange rate correction valid. (bit 3)
    pub const fn pseudorange_rate_correction(self) -> bool {
        self.0 & Self::PSEUDORANGE_RATE_CORRECTION != 0
    }

    /// Sets or clears `pseudorange_rate_correction` (bit 3).
    pub fn set_pseudorange_rate_correction(&mut self, v: bool) {
        if v {
            self.0 |= Self::PSEUDORANGE_RATE_CORRECTION;
        } else {
            self.0 &= !Self::PSEUDORANGE_RATE_CORRECTION;
        }
    }

    /// Not named by the manual. Reserved. (bits 4..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 4
    }

    /// Sets `reserved` (bits 4..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 4) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssDgnssChannelStatusValidFlags {
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
impl crate::json_read::FromJson for GnssDgnssChannelStatusValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// DGNSS information valid flags. Which parameters of the DGNSS information field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssDgnssInfoValidFlags(pub u16);

impl GnssDgnssInfoValidFlags {
    /// Mask of `latest_age` (bit 0).
    pub const LATEST_AGE: u16 = 0x0001;
    /// Mask of `base_station_id` (bit 1).
    pub const BASE_STATION_ID: u16 = 0x0002;
    /// Mask of `base_station_status` (bit 2).
    pub const BASE_STATION_STATUS: u16 = 0x0004;
    /// Mask of `num_channels` (bit 3).
    pub const NUM_CHANNELS: u16 = 0x0008;
    /// Mask of `reserved` (bits 4..=15).
    pub const RESERVED: u16 = 0xFFF0;

    /// Newest (latest) correction age valid. (bit 0)
    pub const fn latest_age(self) -> bool {
        self.0 & Self::LATEST_AGE != 0
    }

    /// Sets or clears `latest_age` (bit 0).
    pub fn set_latest_age(&mut self, v: bool) {
        if v {
            self.0 |= Self::LATEST_AGE;
        } else {
            self.0 &= !Self::LATEST_AGE;
        }
    }

    /// Base station id valid. (bit 1)
    pub const fn base_station_id(self) -> bool {
        self.0 & Self::BASE_STATION_ID != 0
    }

    /// Sets or clears `base_station_id` (bit 1).
    pub fn set_base_station_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::BASE_STATION_ID;
        } else {
            self.0 &= !Self::BASE_STATION_ID;
        }
    }

    /// Base station status valid. (bit 2)
    pub const fn base_station_status(self) -> bool {
        self.0 & Self::BASE_STATION_STATUS != 0
    }

    /// Sets or clears `base_station_status` (bit 2).
    pub fn set_base_station_status(&mut self, v: bool) {
        if v {
            self.0 |= Self::BASE_STATION_STATUS;
        } else {
            self.0 &= !Self::BASE_STATION_STATUS;
        }
    }

    /// Number of DGNSS channels valid. (bit 3)
    pub const fn num_channels(self) -> bool {
        self.0 & Self::NUM_CHANNELS != 0
    }

    /// Sets or clears `num_channels` (bit 3).
    pub fn set_num_channels(&mut self, v: bool) {
        if v {
            self.0 |= Self::NUM_CHANNELS;
        } else {
            self.0 &= !Self::NUM_CHANNELS;
        }
    }

    /// Not named by the manual. Reserved. (bits 4..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 4
    }

    /// Sets `reserved` (bits 4..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 4) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssDgnssInfoValidFlags {
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
impl crate::json_read::FromJson for GnssDgnssInfoValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS DOP valid flags. Which dilution-of-precision values are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssDopValidFlags(pub u16);

impl GnssDopValidFlags {
    /// Mask of `gdop` (bit 0).
    pub const GDOP: u16 = 0x0001;
    /// Mask of `pdop` (bit 1).
    pub const PDOP: u16 = 0x0002;
    /// Mask of `hdop` (bit 2).
    pub const HDOP: u16 = 0x0004;
    /// Mask of `vdop` (bit 3).
    pub const VDOP: u16 = 0x0008;
    /// Mask of `tdop` (bit 4).
    pub const TDOP: u16 = 0x0010;
    /// Mask of `ndop` (bit 5).
    pub const NDOP: u16 = 0x0020;
    /// Mask of `edop` (bit 6).
    pub const EDOP: u16 = 0x0040;
    /// Mask of `flags` (bits 0..=6).
    pub const FLAGS: u16 = 0x007F;
    /// Mask of `reserved` (bits 7..=15).
    pub const RESERVED: u16 = 0xFF80;

    /// Geometric DOP valid. (bit 0)
    pub const fn gdop(self) -> bool {
        self.0 & Self::GDOP != 0
    }

    /// Sets or clears `gdop` (bit 0).
    pub fn set_gdop(&mut self, v: bool) {
        if v {
            self.0 |= Self::GDOP;
        } else {
            self.0 &= !Self::GDOP;
        }
    }

    /// Position DOP valid. (bit 1)
    pub const fn pdop(self) -> bool {
        self.0 & Self::PDOP != 0
    }

    /// Sets or clears `pdop` (bit 1).
    pub fn set_pdop(&mut self, v: bool) {
        if v {
            self.0 |= Self::PDOP;
        } else {
            self.0 &= !Self::PDOP;
        }
    }

    /// Horizontal DOP valid. (bit 2)
    pub const fn hdop(self) -> bool {
        self.0 & Self::HDOP != 0
    }

    /// Sets or clears `hdop` (bit 2).
    pub fn set_hdop(&mut self, v: bool) {
        if v {
            self.0 |= Self::HDOP;
        } else {
            self.0 &= !Self::HDOP;
        }
    }

    /// Vertical DOP valid. (bit 3)
    pub const fn vdop(self) -> bool {
        self.0 & Self::VDOP != 0
    }

    /// Sets or clears `vdop` (bit 3).
    pub fn set_vdop(&mut self, v: bool) {
        if v {
            self.0 |= Self::VDOP;
        } else {
            self.0 &= !Self::VDOP;
        }
    }

    /// Time DOP valid. (bit 4)
    pub const fn tdop(self) -> bool {
        self.0 & Self::TDOP != 0
    }

    /// Sets or clears `tdop` (bit 4).
    pub fn set_tdop(&mut self, v: bool) {
        if v {
            self.0 |= Self::TDOP;
        } else {
            self.0 &= !Self::TDOP;
        }
    }

    /// Northing DOP valid. (bit 5)
    pub const fn ndop(self) -> bool {
        self.0 & Self::NDOP != 0
    }

    /// Sets or clears `ndop` (bit 5).
    pub fn set_ndop(&mut self, v: bool) {
        if v {
            self.0 |= Self::NDOP;
        } else {
            self.0 &= !Self::NDOP;
        }
    }

    /// Easting DOP valid. (bit 6)
    pub const fn edop(self) -> bool {
        self.0 & Self::EDOP != 0
    }

    /// Sets or clears `edop` (bit 6).
    pub fn set_edop(&mut self, v: bool) {
        if v {
            self.0 |= Self::EDOP;
        } else {
            self.0 &= !Self::EDOP;
        }
    }

    /// All flags. (bits 0..=6)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=6); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 7..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 7
    }

    /// Sets `reserved` (bits 7..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 7) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssDopValidFlags {
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
impl crate::json_read::FromJson for GnssDopValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS ECEF position valid flags. Which parameters of a GNSS ECEF position field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssEcefPositionValidFlags(pub u16);

impl GnssEcefPositionValidFlags {
    /// Mask of `position` (bit 0).
    pub const POSITION: u16 = 0x0001;
    /// Mask of `position_accuracy` (bit 1).
    pub const POSITION_ACCURACY: u16 = 0x0002;
    /// Mask of `flags` (bits 0..=1).
    pub const FLAGS: u16 = 0x0003;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// ECEF position valid. (bit 0)
    pub const fn position(self) -> bool {
        self.0 & Self::POSITION != 0
    }

    /// Sets or clears `position` (bit 0).
    pub fn set_position(&mut self, v: bool) {
        if v {
            self.0 |= Self::POSITION;
        } else {
            self.0 &= !Self::POSITION;
        }
    }

    /// Position accuracy valid. (bit 1)
    pub const fn position_accuracy(self) -> bool {
        self.0 & Self::POSITION_ACCURACY != 0
    }

    /// Sets or clears `position_accuracy` (bit 1).
    pub fn set_position_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::POSITION_ACCURACY;
        } else {
            self.0 &= !Self::POSITION_ACCURACY;
        }
    }

    /// All flags. (bits 0..=1)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=1); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssEcefPositionValidFlags {
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
impl crate::json_read::FromJson for GnssEcefPositionValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS ECEF velocity valid flags. Which parameters of a GNSS ECEF velocity field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssEcefVelocityValidFlags(pub u16);

impl GnssEcefVelocityValidFlags {
    /// Mask of `velocity` (bit 0).
    pub const VELOCITY: u16 = 0x0001;
    /// Mask of `velocity_accuracy` (bit 1).
    pub const VELOCITY_ACCURACY: u16 = 0x0002;
    /// Mask of `flags` (bits 0..=1).
    pub const FLAGS: u16 = 0x0003;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// ECEF velocity valid. (bit 0)
    pub const fn velocity(self) -> bool {
        self.0 & Self::VELOCITY != 0
    }

    /// Sets or clears `velocity` (bit 0).
    pub fn set_velocity(&mut self, v: bool) {
        if v {
            self.0 |= Self::VELOCITY;
        } else {
            self.0 &= !Self::VELOCITY;
        }
    }

    /// Velocity accuracy valid. (bit 1)
    pub const fn velocity_accuracy(self) -> bool {
        self.0 & Self::VELOCITY_ACCURACY != 0
    }

    /// Sets or clears `velocity_accuracy` (bit 1).
    pub fn set_velocity_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::VELOCITY_ACCURACY;
        } else {
            self.0 &= !Self::VELOCITY_ACCURACY;
        }
    }

    /// All flags. (bits 0..=1)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=1); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssEcefVelocityValidFlags {
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
impl crate::json_read::FromJson for GnssEcefVelocityValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPS/Galileo/BeiDou ephemeris valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssEphemerisValidFlags(pub u16);

impl GnssEphemerisValidFlags {
    /// Mask of `ephemeris` (bit 0).
    pub const EPHEMERIS: u16 = 0x0001;
    /// Mask of `modern_data` (bit 1).
    pub const MODERN_DATA: u16 = 0x0002;
    /// Mask of `isc_l5` (bit 2).
    pub const ISC_L5: u16 = 0x0004;
    /// Mask of `flags` (bits 0..=2).
    pub const FLAGS: u16 = 0x0007;
    /// Mask of `reserved` (bits 3..=15).
    pub const RESERVED: u16 = 0xFFF8;

    /// Ephemeris data valid. (bit 0)
    pub const fn ephemeris(self) -> bool {
        self.0 & Self::EPHEMERIS != 0
    }

    /// Sets or clears `ephemeris` (bit 0).
    pub fn set_ephemeris(&mut self, v: bool) {
        if v {
            self.0 |= Self::EPHEMERIS;
        } else {
            self.0 &= !Self::EPHEMERIS;
        }
    }

    /// Modernized navigation data present (the manual gives only the name, not which parameters it covers). (bit 1)
    pub const fn modern_data(self) -> bool {
        self.0 & Self::MODERN_DATA != 0
    }

    /// Sets or clears `modern_data` (bit 1).
    pub fn set_modern_data(&mut self, v: bool) {
        if v {
            self.0 |= Self::MODERN_DATA;
        } else {
            self.0 &= !Self::MODERN_DATA;
        }
    }

    /// isc_l2c holds the L5 inter-signal correction instead of L2. (bit 2)
    pub const fn isc_l5(self) -> bool {
        self.0 & Self::ISC_L5 != 0
    }

    /// Sets or clears `isc_l5` (bit 2).
    pub fn set_isc_l5(&mut self, v: bool) {
        if v {
            self.0 |= Self::ISC_L5;
        } else {
            self.0 &= !Self::ISC_L5;
        }
    }

    /// All valid flags (the manual's 'flags 0-2' entry). (bits 0..=2)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=2); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manual. Reserved. (bits 3..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 3
    }

    /// Sets `reserved` (bits 3..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 3) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssEphemerisValidFlags {
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
impl crate::json_read::FromJson for GnssEphemerisValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS fix flags. Corrections used in the position fix.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssFixFlags(pub u16);

impl GnssFixFlags {
    /// Mask of `sbas_used` (bit 0).
    pub const SBAS_USED: u16 = 0x0001;
    /// Mask of `dgnss_used` (bit 1).
    pub const DGNSS_USED: u16 = 0x0002;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// SBAS corrections used. (bit 0)
    pub const fn sbas_used(self) -> bool {
        self.0 & Self::SBAS_USED != 0
    }

    /// Sets or clears `sbas_used` (bit 0).
    pub fn set_sbas_used(&mut self, v: bool) {
        if v {
            self.0 |= Self::SBAS_USED;
        } else {
            self.0 &= !Self::SBAS_USED;
        }
    }

    /// Differential (DGNSS) corrections used. (bit 1)
    pub const fn dgnss_used(self) -> bool {
        self.0 & Self::DGNSS_USED != 0
    }

    /// Sets or clears `dgnss_used` (bit 1).
    pub fn set_dgnss_used(&mut self, v: bool) {
        if v {
            self.0 |= Self::DGNSS_USED;
        } else {
            self.0 &= !Self::DGNSS_USED;
        }
    }

    /// Not named by the manuals. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssFixFlags {
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
impl crate::json_read::FromJson for GnssFixFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS fix information valid flags. Which parameters of a GNSS fix information field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssFixInfoValidFlags(pub u16);

impl GnssFixInfoValidFlags {
    /// Mask of `fix_type` (bit 0).
    pub const FIX_TYPE: u16 = 0x0001;
    /// Mask of `num_sv` (bit 1).
    pub const NUM_SV: u16 = 0x0002;
    /// Mask of `fix_flags` (bit 2).
    pub const FIX_FLAGS: u16 = 0x0004;
    /// Mask of `flags` (bits 0..=2).
    pub const FLAGS: u16 = 0x0007;
    /// Mask of `reserved` (bits 3..=15).
    pub const RESERVED: u16 = 0xFFF8;

    /// Fix type valid. (bit 0)
    pub const fn fix_type(self) -> bool {
        self.0 & Self::FIX_TYPE != 0
    }

    /// Sets or clears `fix_type` (bit 0).
    pub fn set_fix_type(&mut self, v: bool) {
        if v {
            self.0 |= Self::FIX_TYPE;
        } else {
            self.0 &= !Self::FIX_TYPE;
        }
    }

    /// Number of satellites valid. (bit 1)
    pub const fn num_sv(self) -> bool {
        self.0 & Self::NUM_SV != 0
    }

    /// Sets or clears `num_sv` (bit 1).
    pub fn set_num_sv(&mut self, v: bool) {
        if v {
            self.0 |= Self::NUM_SV;
        } else {
            self.0 &= !Self::NUM_SV;
        }
    }

    /// Fix flags valid. (bit 2)
    pub const fn fix_flags(self) -> bool {
        self.0 & Self::FIX_FLAGS != 0
    }

    /// Sets or clears `fix_flags` (bit 2).
    pub fn set_fix_flags(&mut self, v: bool) {
        if v {
            self.0 |= Self::FIX_FLAGS;
        } else {
            self.0 &= !Self::FIX_FLAGS;
        }
    }

    /// All flags. (bits 0..=2)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=2); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 3..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 3
    }

    /// Sets `reserved` (bits 3..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 3) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssFixInfoValidFlags {
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
impl crate::json_read::FromJson for GnssFixInfoValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS fix type (CV7). Type of position fix a CV7 GNSS receiver reports.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssFixTypeCv7(pub u8);

impl GnssFixTypeCv7 {
    /// 3D fix.
    pub const FIX_3D: Self = Self(0);
    /// 2D fix.
    pub const FIX_2D: Self = Self(1);
    /// Time only.
    pub const FIX_TIME_ONLY: Self = Self(2);
    /// No fix.
    pub const FIX_NONE: Self = Self(3);
    /// Invalid.
    pub const FIX_INVALID: Self = Self(4);
    /// RTK solution, float ambiguities.
    pub const FIX_RTK_FLOAT: Self = Self(5);
    /// RTK solution, fixed ambiguities.
    pub const FIX_RTK_FIXED: Self = Self(6);
    /// Differential (DGNSS) solution.
    pub const FIX_DIFFERENTIAL: Self = Self(7);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("fix_3d"),
            1 => Some("fix_2d"),
            2 => Some("fix_time_only"),
            3 => Some("fix_none"),
            4 => Some("fix_invalid"),
            5 => Some("fix_rtk_float"),
            6 => Some("fix_rtk_fixed"),
            7 => Some("fix_differential"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "fix_3d" => Some(Self::FIX_3D),
            "fix_2d" => Some(Self::FIX_2D),
            "fix_time_only" => Some(Self::FIX_TIME_ONLY),
            "fix_none" => Some(Self::FIX_NONE),
            "fix_invalid" => Some(Self::FIX_INVALID),
            "fix_rtk_float" => Some(Self::FIX_RTK_FLOAT),
            "fix_rtk_fixed" => Some(Self::FIX_RTK_FIXED),
            "fix_differential" => Some(Self::FIX_DIFFERENTIAL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssFixTypeCv7 {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssFixTypeCv7({} {})", self.0, name),
            None => write!(f, "GnssFixTypeCv7({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssFixTypeCv7 {
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
impl crate::json_read::FromJson for GnssFixTypeCv7 {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS fix type (GX5-45). Type of position fix the GX5-45 GNSS receiver reports.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssFixTypeGx5(pub u8);

impl GnssFixTypeGx5 {
    /// 3D fix.
    pub const FIX_3D: Self = Self(0);
    /// 2D fix.
    pub const FIX_2D: Self = Self(1);
    /// Time only.
    pub const FIX_TIME_ONLY: Self = Self(2);
    /// No fix.
    pub const FIX_NONE: Self = Self(3);
    /// Invalid.
    pub const FIX_INVALID: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("fix_3d"),
            1 => Some("fix_2d"),
            2 => Some("fix_time_only"),
            3 => Some("fix_none"),
            4 => Some("fix_invalid"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "fix_3d" => Some(Self::FIX_3D),
            "fix_2d" => Some(Self::FIX_2D),
            "fix_time_only" => Some(Self::FIX_TIME_ONLY),
            "fix_none" => Some(Self::FIX_NONE),
            "fix_invalid" => Some(Self::FIX_INVALID),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssFixTypeGx5 {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssFixTypeGx5({} {})", self.0, name),
            None => write!(f, "GnssFixTypeGx5({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssFixTypeGx5 {
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
impl crate::json_read::FromJson for GnssFixTypeGx5 {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Galileo signals enabled.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssGalileoSignals(pub u8);

impl GnssGalileoSignals {
    /// Mask of `e1` (bit 0).
    pub const E1: u8 = 0x01;
    /// Mask of `e5b` (bit 1).
    pub const E5B: u8 = 0x02;
    /// Mask of `e5a` (bit 2).
    pub const E5A: u8 = 0x04;

    /// Enable E1. (bit 0)
    pub const fn e1(self) -> bool {
        self.0 & Self::E1 != 0
    }

    /// Sets or clears `e1` (bit 0).
    pub fn set_e1(&mut self, v: bool) {
        if v {
            self.0 |= Self::E1;
        } else {
            self.0 &= !Self::E1;
        }
    }

    /// Enable E5B. (bit 1)
    pub const fn e5b(self) -> bool {
        self.0 & Self::E5B != 0
    }

    /// Sets or clears `e5b` (bit 1).
    pub fn set_e5b(&mut self, v: bool) {
        if v {
            self.0 |= Self::E5B;
        } else {
            self.0 &= !Self::E5B;
        }
    }

    /// Enable E5A. (bit 2)
    pub const fn e5a(self) -> bool {
        self.0 & Self::E5A != 0
    }

    /// Sets or clears `e5a` (bit 2).
    pub fn set_e5a(&mut self, v: bool) {
        if v {
            self.0 |= Self::E5A;
        } else {
            self.0 &= !Self::E5A;
        }
    }
}

impl crate::wire::Wire for GnssGalileoSignals {
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
impl crate::json_read::FromJson for GnssGalileoSignals {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GLONASS ephemeris valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssGlonassEphemerisValidFlags(pub u16);

impl GnssGlonassEphemerisValidFlags {
    /// Mask of `ephemeris` (bit 0).
    pub const EPHEMERIS: u16 = 0x0001;
    /// Mask of `flags` (bit 0).
    pub const FLAGS: u16 = 0x0001;
    /// Mask of `reserved` (bits 1..=15).
    pub const RESERVED: u16 = 0xFFFE;

    /// Ephemeris data valid. (bit 0)
    pub const fn ephemeris(self) -> bool {
        self.0 & Self::EPHEMERIS != 0
    }

    /// Sets or clears `ephemeris` (bit 0).
    pub fn set_ephemeris(&mut self, v: bool) {
        if v {
            self.0 |= Self::EPHEMERIS;
        } else {
            self.0 &= !Self::EPHEMERIS;
        }
    }

    /// All valid flags (the manual's 'flags 0' entry: the single bit 0). (bit 0)
    pub const fn flags(self) -> bool {
        self.0 & Self::FLAGS != 0
    }

    /// Sets or clears `flags` (bit 0).
    pub fn set_flags(&mut self, v: bool) {
        if v {
            self.0 |= Self::FLAGS;
        } else {
            self.0 &= !Self::FLAGS;
        }
    }

    /// Not named by the manual. Reserved. (bits 1..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 1
    }

    /// Sets `reserved` (bits 1..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 1) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssGlonassEphemerisValidFlags {
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
impl crate::json_read::FromJson for GnssGlonassEphemerisValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GLONASS satellite type.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssGlonassSatelliteType(pub u8);

impl GnssGlonassSatelliteType {
    /// GLONASS satellite.
    pub const GLONASS: Self = Self(0);
    /// GLONASS-M satellite.
    pub const GLONASS_M: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("glonass"),
            1 => Some("glonass_m"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "glonass" => Some(Self::GLONASS),
            "glonass_m" => Some(Self::GLONASS_M),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssGlonassSatelliteType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssGlonassSatelliteType({} {})", self.0, name),
            None => write!(f, "GnssGlonassSatelliteType({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssGlonassSatelliteType {
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
impl crate::json_read::FromJson for GnssGlonassSatelliteType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GLONASS signals enabled.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssGlonassSignals(pub u8);

impl GnssGlonassSignals {
    /// Mask of `l1of` (bit 0).
    pub const L1OF: u8 = 0x01;
    /// Mask of `l2of` (bit 1).
    pub const L2OF: u8 = 0x02;

    /// Enable L1OF. (bit 0)
    pub const fn l1of(self) -> bool {
        self.0 & Self::L1OF != 0
    }

    /// Sets or clears `l1of` (bit 0).
    pub fn set_l1of(&mut self, v: bool) {
        if v {
            self.0 |= Self::L1OF;
        } else {
            self.0 &= !Self::L1OF;
        }
    }

    /// Enable L2OF. (bit 1)
    pub const fn l2of(self) -> bool {
        self.0 & Self::L2OF != 0
    }

    /// Sets or clears `l2of` (bit 1).
    pub fn set_l2of(&mut self, v: bool) {
        if v {
            self.0 |= Self::L2OF;
        } else {
            self.0 &= !Self::L2OF;
        }
    }
}

impl crate::wire::Wire for GnssGlonassSignals {
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
impl crate::json_read::FromJson for GnssGlonassSignals {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPS signals enabled.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssGpsSignals(pub u8);

impl GnssGpsSignals {
    /// Mask of `l1ca` (bit 0).
    pub const L1CA: u8 = 0x01;
    /// Mask of `l2c` (bit 1).
    pub const L2C: u8 = 0x02;
    /// Mask of `l5` (bit 2).
    pub const L5: u8 = 0x04;

    /// Enable L1 C/A. (bit 0)
    pub const fn l1ca(self) -> bool {
        self.0 & Self::L1CA != 0
    }

    /// Sets or clears `l1ca` (bit 0).
    pub fn set_l1ca(&mut self, v: bool) {
        if v {
            self.0 |= Self::L1CA;
        } else {
            self.0 &= !Self::L1CA;
        }
    }

    /// Enable L2C. (bit 1)
    pub const fn l2c(self) -> bool {
        self.0 & Self::L2C != 0
    }

    /// Sets or clears `l2c` (bit 1).
    pub fn set_l2c(&mut self, v: bool) {
        if v {
            self.0 |= Self::L2C;
        } else {
            self.0 &= !Self::L2C;
        }
    }

    /// Enable L5. (bit 2)
    pub const fn l5(self) -> bool {
        self.0 & Self::L5 != 0
    }

    /// Sets or clears `l5` (bit 2).
    pub fn set_l5(&mut self, v: bool) {
        if v {
            self.0 |= Self::L5;
        } else {
            self.0 &= !Self::L5;
        }
    }
}

impl crate::wire::Wire for GnssGpsSignals {
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
impl crate::json_read::FromJson for GnssGpsSignals {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS GPS time valid flags. Validity of a GNSS GPS time field.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssGpsTimeValidFlags(pub u16);

impl GnssGpsTimeValidFlags {
    /// Mask of `tow` (bit 0).
    pub const TOW: u16 = 0x0001;
    /// Mask of `week_number` (bit 1).
    pub const WEEK_NUMBER: u16 = 0x0002;
    /// Mask of `flags` (bits 0..=1).
    pub const FLAGS: u16 = 0x0003;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// Time of week valid. (bit 0)
    pub const fn tow(self) -> bool {
        self.0 & Self::TOW != 0
    }

    /// Sets or clears `tow` (bit 0).
    pub fn set_tow(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW;
        } else {
            self.0 &= !Self::TOW;
        }
    }

    /// Week number valid. (bit 1)
    pub const fn week_number(self) -> bool {
        self.0 & Self::WEEK_NUMBER != 0
    }

    /// Sets or clears `week_number` (bit 1).
    pub fn set_week_number(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER;
        } else {
            self.0 &= !Self::WEEK_NUMBER;
        }
    }

    /// All flags. (bits 0..=1)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=1); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssGpsTimeValidFlags {
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
impl crate::json_read::FromJson for GnssGpsTimeValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS hardware status valid flags. Which parameters of a GNSS hardware status field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssHardwareStatusValidFlags(pub u16);

impl GnssHardwareStatusValidFlags {
    /// Mask of `sensor_state` (bit 0).
    pub const SENSOR_STATE: u16 = 0x0001;
    /// Mask of `antenna_state` (bit 1).
    pub const ANTENNA_STATE: u16 = 0x0002;
    /// Mask of `antenna_power` (bit 2).
    pub const ANTENNA_POWER: u16 = 0x0004;
    /// Mask of `flags` (bits 0..=2).
    pub const FLAGS: u16 = 0x0007;
    /// Mask of `reserved` (bits 3..=15).
    pub const RESERVED: u16 = 0xFFF8;

    /// Receiver (sensor) state valid. (bit 0)
    pub const fn sensor_state(self) -> bool {
        self.0 & Self::SENSOR_STATE != 0
    }

    /// Sets or clears `sensor_state` (bit 0).
    pub fn set_sensor_state(&mut self, v: bool) {
        if v {
            self.0 |= Self::SENSOR_STATE;
        } else {
            self.0 &= !Self::SENSOR_STATE;
        }
    }

    /// Antenna state valid. (bit 1)
    pub const fn antenna_state(self) -> bool {
        self.0 & Self::ANTENNA_STATE != 0
    }

    /// Sets or clears `antenna_state` (bit 1).
    pub fn set_antenna_state(&mut self, v: bool) {
        if v {
            self.0 |= Self::ANTENNA_STATE;
        } else {
            self.0 &= !Self::ANTENNA_STATE;
        }
    }

    /// Antenna power valid. (bit 2)
    pub const fn antenna_power(self) -> bool {
        self.0 & Self::ANTENNA_POWER != 0
    }

    /// Sets or clears `antenna_power` (bit 2).
    pub fn set_antenna_power(&mut self, v: bool) {
        if v {
            self.0 |= Self::ANTENNA_POWER;
        } else {
            self.0 &= !Self::ANTENNA_POWER;
        }
    }

    /// All flags. (bits 0..=2)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=2); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 3..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 3
    }

    /// Sets `reserved` (bits 3..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 3) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssHardwareStatusValidFlags {
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
impl crate::json_read::FromJson for GnssHardwareStatusValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPS leap seconds valid flags. Validity of the GPS leap seconds field.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssLeapSecondsValidFlags(pub u16);

impl GnssLeapSecondsValidFlags {
    /// Mask of `reserved_0` (bit 0).
    pub const RESERVED_0: u16 = 0x0001;
    /// Mask of `leap_seconds` (bit 1).
    pub const LEAP_SECONDS: u16 = 0x0002;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// Not named by the manual. Reserved. (bit 0)
    pub const fn reserved_0(self) -> bool {
        self.0 & Self::RESERVED_0 != 0
    }

    /// Sets or clears `reserved_0` (bit 0).
    pub fn set_reserved_0(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_0;
        } else {
            self.0 &= !Self::RESERVED_0;
        }
    }

    /// Leap seconds valid. (bit 1)
    pub const fn leap_seconds(self) -> bool {
        self.0 & Self::LEAP_SECONDS != 0
    }

    /// Sets or clears `leap_seconds` (bit 1).
    pub fn set_leap_seconds(&mut self, v: bool) {
        if v {
            self.0 |= Self::LEAP_SECONDS;
        } else {
            self.0 &= !Self::LEAP_SECONDS;
        }
    }

    /// Not named by the manual. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssLeapSecondsValidFlags {
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
impl crate::json_read::FromJson for GnssLeapSecondsValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS LLH position valid flags. Which parameters of a GNSS LLH position field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssLlhPositionValidFlags(pub u16);

impl GnssLlhPositionValidFlags {
    /// Mask of `lat_lon` (bit 0).
    pub const LAT_LON: u16 = 0x0001;
    /// Mask of `ellipsoid_height` (bit 1).
    pub const ELLIPSOID_HEIGHT: u16 = 0x0002;
    /// Mask of `msl_height` (bit 2).
    pub const MSL_HEIGHT: u16 = 0x0004;
    /// Mask of `horizontal_accuracy` (bit 3).
    pub const HORIZONTAL_ACCURACY: u16 = 0x0008;
    /// Mask of `vertical_accuracy` (bit 4).
    pub const VERTICAL_ACCURACY: u16 = 0x0010;
    /// Mask of `flags` (bits 0..=4).
    pub const FLAGS: u16 = 0x001F;
    /// Mask of `reserved` (bits 5..=15).
    pub const RESERVED: u16 = 0xFFE0;

    /// Latitude and longitude valid. (bit 0)
    pub const fn lat_lon(self) -> bool {
        self.0 & Self::LAT_LON != 0
    }

    /// Sets or clears `lat_lon` (bit 0).
    pub fn set_lat_lon(&mut self, v: bool) {
        if v {
            self.0 |= Self::LAT_LON;
        } else {
            self.0 &= !Self::LAT_LON;
        }
    }

    /// Height above ellipsoid valid. (bit 1)
    pub const fn ellipsoid_height(self) -> bool {
        self.0 & Self::ELLIPSOID_HEIGHT != 0
    }

    /// Sets or clears `ellipsoid_height` (bit 1).
    pub fn set_ellipsoid_height(&mut self, v: bool) {
        if v {
            self.0 |= Self::ELLIPSOID_HEIGHT;
        } else {
            self.0 &= !Self::ELLIPSOID_HEIGHT;
        }
    }

    /// Height above mean sea level valid. (bit 2)
    pub const fn msl_height(self) -> bool {
        self.0 & Self::MSL_HEIGHT != 0
    }

    /// Sets or clears `msl_height` (bit 2).
    pub fn set_msl_height(&mut self, v: bool) {
        if v {
            self.0 |= Self::MSL_HEIGHT;
        } else {
            self.0 &= !Self::MSL_HEIGHT;
        }
    }

    /// Horizontal accuracy valid. (bit 3)
    pub const fn horizontal_accuracy(self) -> bool {
        self.0 & Self::HORIZONTAL_ACCURACY != 0
    }

    /// Sets or clears `horizontal_accuracy` (bit 3).
    pub fn set_horizontal_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::HORIZONTAL_ACCURACY;
        } else {
            self.0 &= !Self::HORIZONTAL_ACCURACY;
        }
    }

    /// Vertical accuracy valid. (bit 4)
    pub const fn vertical_accuracy(self) -> bool {
        self.0 & Self::VERTICAL_ACCURACY != 0
    }

    /// Sets or clears `vertical_accuracy` (bit 4).
    pub fn set_vertical_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::VERTICAL_ACCURACY;
        } else {
            self.0 &= !Self::VERTICAL_ACCURACY;
        }
    }

    /// All flags. (bits 0..=4)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=4); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 5..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 5
    }

    /// Sets `reserved` (bits 5..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 5) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssLlhPositionValidFlags {
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
impl crate::json_read::FromJson for GnssLlhPositionValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS NED velocity valid flags. Which parameters of a GNSS NED velocity field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssNedVelocityValidFlags(pub u16);

impl GnssNedVelocityValidFlags {
    /// Mask of `velocity` (bit 0).
    pub const VELOCITY: u16 = 0x0001;
    /// Mask of `speed_3d` (bit 1).
    pub const SPEED_3D: u16 = 0x0002;
    /// Mask of `ground_speed` (bit 2).
    pub const GROUND_SPEED: u16 = 0x0004;
    /// Mask of `heading` (bit 3).
    pub const HEADING: u16 = 0x0008;
    /// Mask of `speed_accuracy` (bit 4).
    pub const SPEED_ACCURACY: u16 = 0x0010;
    /// Mask of `heading_accuracy` (bit 5).
    pub const HEADING_ACCURACY: u16 = 0x0020;
    /// Mask of `flags` (bits 0..=5).
    pub const FLAGS: u16 = 0x003F;
    /// Mask of `reserved` (bits 6..=15).
    pub const RESERVED: u16 = 0xFFC0;

    /// NED velocity vector valid. (bit 0)
    pub const fn velocity(self) -> bool {
        self.0 & Self::VELOCITY != 0
    }

    /// Sets or clears `velocity` (bit 0).
    pub fn set_velocity(&mut self, v: bool) {
        if v {
            self.0 |= Self::VELOCITY;
        } else {
            self.0 &= !Self::VELOCITY;
        }
    }

    /// 3D speed valid. (bit 1)
    pub const fn speed_3d(self) -> bool {
        self.0 & Self::SPEED_3D != 0
    }

    /// Sets or clears `speed_3d` (bit 1).
    pub fn set_speed_3d(&mut self, v: bool) {
        if v {
            self.0 |= Self::SPEED_3D;
        } else {
            self.0 &= !Self::SPEED_3D;
        }
    }

    /// Ground speed valid. (bit 2)
    pub const fn ground_speed(self) -> bool {
        self.0 & Self::GROUND_SPEED != 0
    }

    /// Sets or clears `ground_speed` (bit 2).
    pub fn set_ground_speed(&mut self, v: bool) {
        if v {
            self.0 |= Self::GROUND_SPEED;
        } else {
            self.0 &= !Self::GROUND_SPEED;
        }
    }

    /// Heading valid. (bit 3)
    pub const fn heading(self) -> bool {
        self.0 & Self::HEADING != 0
    }

    /// Sets or clears `heading` (bit 3).
    pub fn set_heading(&mut self, v: bool) {
        if v {
            self.0 |= Self::HEADING;
        } else {
            self.0 &= !Self::HEADING;
        }
    }

    /// Speed accuracy valid. (bit 4)
    pub const fn speed_accuracy(self) -> bool {
        self.0 & Self::SPEED_ACCURACY != 0
    }

    /// Sets or clears `speed_accuracy` (bit 4).
    pub fn set_speed_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::SPEED_ACCURACY;
        } else {
            self.0 &= !Self::SPEED_ACCURACY;
        }
    }

    /// Heading accuracy valid. (bit 5)
    pub const fn heading_accuracy(self) -> bool {
        self.0 & Self::HEADING_ACCURACY != 0
    }

    /// Sets or clears `heading_accuracy` (bit 5).
    pub fn set_heading_accuracy(&mut self, v: bool) {
        if v {
            self.0 |= Self::HEADING_ACCURACY;
        } else {
            self.0 &= !Self::HEADING_ACCURACY;
        }
    }

    /// All flags. (bits 0..=5)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=5); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manuals. Reserved. (bits 6..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 6
    }

    /// Sets `reserved` (bits 6..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 6) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssNedVelocityValidFlags {
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
impl crate::json_read::FromJson for GnssNedVelocityValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Raw observation valid flags. Which parameters of a raw observation field hold valid data.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssRawValidFlags(pub u16);

impl GnssRawValidFlags {
    /// Mask of `tow` (bit 0).
    pub const TOW: u16 = 0x0001;
    /// Mask of `week_number` (bit 1).
    pub const WEEK_NUMBER: u16 = 0x0002;
    /// Mask of `receiver_id` (bit 2).
    pub const RECEIVER_ID: u16 = 0x0004;
    /// Mask of `tracking_channel` (bit 3).
    pub const TRACKING_CHANNEL: u16 = 0x0008;
    /// Mask of `gnss_id` (bit 4).
    pub const GNSS_ID: u16 = 0x0010;
    /// Mask of `satellite_id` (bit 5).
    pub const SATELLITE_ID: u16 = 0x0020;
    /// Mask of `signal_id` (bit 6).
    pub const SIGNAL_ID: u16 = 0x0040;
    /// Mask of `signal_strength` (bit 7).
    pub const SIGNAL_STRENGTH: u16 = 0x0080;
    /// Mask of `quality` (bit 8).
    pub const QUALITY: u16 = 0x0100;
    /// Mask of `pseudorange` (bit 9).
    pub const PSEUDORANGE: u16 = 0x0200;
    /// Mask of `carrier_phase` (bit 10).
    pub const CARRIER_PHASE: u16 = 0x0400;
    /// Mask of `doppler` (bit 11).
    pub const DOPPLER: u16 = 0x0800;
    /// Mask of `range_uncertainty` (bit 12).
    pub const RANGE_UNCERTAINTY: u16 = 0x1000;
    /// Mask of `carrier_phase_uncertainty` (bit 13).
    pub const CARRIER_PHASE_UNCERTAINTY: u16 = 0x2000;
    /// Mask of `doppler_uncertainty` (bit 14).
    pub const DOPPLER_UNCERTAINTY: u16 = 0x4000;
    /// Mask of `lock_time` (bit 15).
    pub const LOCK_TIME: u16 = 0x8000;
    /// Mask of `flags` (bits 0..=15).
    pub const FLAGS: u16 = 0xFFFF;

    /// Time of week valid. (bit 0)
    pub const fn tow(self) -> bool {
        self.0 & Self::TOW != 0
    }

    /// Sets or clears `tow` (bit 0).
    pub fn set_tow(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW;
        } else {
            self.0 &= !Self::TOW;
        }
    }

    /// Week number valid. (bit 1)
    pub const fn week_number(self) -> bool {
        self.0 & Self::WEEK_NUMBER != 0
    }

    /// Sets or clears `week_number` (bit 1).
    pub fn set_week_number(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER;
        } else {
            self.0 &= !Self::WEEK_NUMBER;
        }
    }

    /// Receiver id valid. (bit 2)
    pub const fn receiver_id(self) -> bool {
        self.0 & Self::RECEIVER_ID != 0
    }

    /// Sets or clears `receiver_id` (bit 2).
    pub fn set_receiver_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::RECEIVER_ID;
        } else {
            self.0 &= !Self::RECEIVER_ID;
        }
    }

    /// Tracking channel valid. (bit 3)
    pub const fn tracking_channel(self) -> bool {
        self.0 & Self::TRACKING_CHANNEL != 0
    }

    /// Sets or clears `tracking_channel` (bit 3).
    pub fn set_tracking_channel(&mut self, v: bool) {
        if v {
            self.0 |= Self::TRACKING_CHANNEL;
        } else {
            self.0 &= !Self::TRACKING_CHANNEL;
        }
    }

    /// Constellation id valid. (bit 4)
    pub const fn gnss_id(self) -> bool {
        self.0 & Self::GNSS_ID != 0
    }

    /// Sets or clears `gnss_id` (bit 4).
    pub fn set_gnss_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_ID;
        } else {
            self.0 &= !Self::GNSS_ID;
        }
    }

    /// Satellite id valid. (bit 5)
    pub const fn satellite_id(self) -> bool {
        self.0 & Self::SATELLITE_ID != 0
    }

    /// Sets or clears `satellite_id` (bit 5).
    pub fn set_satellite_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::SATELLITE_ID;
        } else {
            self.0 &= !Self::SATELLITE_ID;
        }
    }

    /// Signal id valid. (bit 6)
    pub const fn signal_id(self) -> bool {
        self.0 & Self::SIGNAL_ID != 0
    }

    /// Sets or clears `signal_id` (bit 6).
    pub fn set_signal_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::SIGNAL_ID;
        } else {
            self.0 &= !Self::SIGNAL_ID;
        }
    }

    /// Signal strength valid. (bit 7)
    pub const fn signal_strength(self) -> bool {
        self.0 & Self::SIGNAL_STRENGTH != 0
    }

    /// Sets or clears `signal_strength` (bit 7).
    pub fn set_signal_strength(&mut self, v: bool) {
        if v {
            self.0 |= Self::SIGNAL_STRENGTH;
        } else {
            self.0 &= !Self::SIGNAL_STRENGTH;
        }
    }

    /// Quality valid. (bit 8)
    pub const fn quality(self) -> bool {
        self.0 & Self::QUALITY != 0
    }

    /// Sets or clears `quality` (bit 8).
    pub fn set_quality(&mut self, v: bool) {
        if v {
            self.0 |= Self::QUALITY;
        } else {
            self.0 &= !Self::QUALITY;
        }
    }

    /// Pseudorange valid. (bit 9)
    pub const fn pseudorange(self) -> bool {
        self.0 & Self::PSEUDORANGE != 0
    }

    /// Sets or clears `pseudorange` (bit 9).
    pub fn set_pseudorange(&mut self, v: bool) {
        if v {
            self.0 |= Self::PSEUDORANGE;
        } else {
            self.0 &= !Self::PSEUDORANGE;
        }
    }

    /// Carrier phase valid. (bit 10)
    pub const fn carrier_phase(self) -> bool {
        self.0 & Self::CARRIER_PHASE != 0
    }

    /// Sets or clears `carrier_phase` (bit 10).
    pub fn set_carrier_phase(&mut self, v: bool) {
        if v {
            self.0 |= Self::CARRIER_PHASE;
        } else {
            self.0 &= !Self::CARRIER_PHASE;
        }
    }

    /// Doppler valid. (bit 11)
    pub const fn doppler(self) -> bool {
        self.0 & Self::DOPPLER != 0
    }

    /// Sets or clears `doppler` (bit 11).
    pub fn set_doppler(&mut self, v: bool) {
        if v {
            self.0 |= Self::DOPPLER;
        } else {
            self.0 &= !Self::DOPPLER;
        }
    }

    /// Pseudorange uncertainty valid. (bit 12)
    pub const fn range_uncertainty(self) -> bool {
        self.0 & Self::RANGE_UNCERTAINTY != 0
    }

    /// Sets or clears `range_uncertainty` (bit 12).
    pub fn set_range_uncertainty(&mut self, v: bool) {
        if v {
            self.0 |= Self::RANGE_UNCERTAINTY;
        } else {
            self.0 &= !Self::RANGE_UNCERTAINTY;
        }
    }

    /// Carrier phase uncertainty valid. (bit 13)
    pub const fn carrier_phase_uncertainty(self) -> bool {
        self.0 & Self::CARRIER_PHASE_UNCERTAINTY != 0
    }

    /// Sets or clears `carrier_phase_uncertainty` (bit 13).
    pub fn set_carrier_phase_uncertainty(&mut self, v: bool) {
        if v {
            self.0 |= Self::CARRIER_PHASE_UNCERTAINTY;
        } else {
            self.0 &= !Self::CARRIER_PHASE_UNCERTAINTY;
        }
    }

    /// Doppler uncertainty valid. (bit 14)
    pub const fn doppler_uncertainty(self) -> bool {
        self.0 & Self::DOPPLER_UNCERTAINTY != 0
    }

    /// Sets or clears `doppler_uncertainty` (bit 14).
    pub fn set_doppler_uncertainty(&mut self, v: bool) {
        if v {
            self.0 |= Self::DOPPLER_UNCERTAINTY;
        } else {
            self.0 &= !Self::DOPPLER_UNCERTAINTY;
        }
    }

    /// Lock time valid. (bit 15)
    pub const fn lock_time(self) -> bool {
        self.0 & Self::LOCK_TIME != 0
    }

    /// Sets or clears `lock_time` (bit 15).
    pub fn set_lock_time(&mut self, v: bool) {
        if v {
            self.0 |= Self::LOCK_TIME;
        } else {
            self.0 &= !Self::LOCK_TIME;
        }
    }

    /// All valid flags (the manual's 'flags 0-15' entry). (bits 0..=15)
    pub const fn flags(self) -> u16 {
        self.0
    }

    /// Sets `flags` (bits 0..=15); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = v;
    }
}

impl crate::wire::Wire for GnssRawValidFlags {
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
impl crate::json_read::FromJson for GnssRawValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS receiver information. Identity of one physical GNSS receiver in the device.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssReceiverInfoEntry {
    /// Receiver id (1, 2, ...).
    pub receiver_id: u8,
    /// MIP data descriptor set of this receiver's data.
    pub mip_data_descriptor_set: u8,
    /// ASCII, comma-delimited: module name/model, firmware version.
    pub description: crate::wire::Str<32>,
}

impl Default for GnssReceiverInfoEntry {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssReceiverInfoEntry {
    const ZERO: Self = Self {
        receiver_id: <u8 as crate::wire::Wire>::ZERO,
        mip_data_descriptor_set: <u8 as crate::wire::Wire>::ZERO,
        description: <crate::wire::Str<32> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(34);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_receiver_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("receiver_id"))?;
        let p_mip_data_descriptor_set =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("mip_data_descriptor_set"))?;
        let p_description = <crate::wire::Str<32> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("description"))?;
        Ok(Self {
            receiver_id: p_receiver_id,
            mip_data_descriptor_set: p_mip_data_descriptor_set,
            description: p_description,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.receiver_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_id"))?;
        let v = &self.mip_data_descriptor_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mip_data_descriptor_set"))?;
        let v = &self.description;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("description"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.receiver_id;
        crate::json::key(w, &mut first, "receiver_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mip_data_descriptor_set;
        crate::json::key(w, &mut first, "mip_data_descriptor_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.description;
        crate::json::key(w, &mut first, "description")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssReceiverInfoEntry {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["receiver_id", "mip_data_descriptor_set", "description"],
        )?;
        let p_receiver_id = o.req("receiver_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_mip_data_descriptor_set = o.req(
            "mip_data_descriptor_set",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_description = o.req(
            "description",
            <crate::wire::Str<32> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            receiver_id: p_receiver_id,
            mip_data_descriptor_set: p_mip_data_descriptor_set,
            description: p_description,
        })
    }
}

/// GNSS receiver (sensor) state. Power state of the GNSS receiver (GX5-45 "Sensor State", CV7 "Receiver State").
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssReceiverState(pub u8);

impl GnssReceiverState {
    /// Receiver off.
    pub const OFF: Self = Self(0);
    /// Receiver on.
    pub const ON: Self = Self(1);
    /// State unknown.
    pub const UNKNOWN: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("off"),
            1 => Some("on"),
            2 => Some("unknown"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "off" => Some(Self::OFF),
            "on" => Some(Self::ON),
            "unknown" => Some(Self::UNKNOWN),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssReceiverState {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssReceiverState({} {})", self.0, name),
            None => write!(f, "GnssReceiverState({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssReceiverState {
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
impl crate::json_read::FromJson for GnssReceiverState {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Satellite status valid flags. Which parameters of a satellite status field hold valid data.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssSatelliteStatusValidFlags(pub u16);

impl GnssSatelliteStatusValidFlags {
    /// Mask of `tow` (bit 0).
    pub const TOW: u16 = 0x0001;
    /// Mask of `week_number` (bit 1).
    pub const WEEK_NUMBER: u16 = 0x0002;
    /// Mask of `gnss_id` (bit 2).
    pub const GNSS_ID: u16 = 0x0004;
    /// Mask of `satellite_id` (bit 3).
    pub const SATELLITE_ID: u16 = 0x0008;
    /// Mask of `elevation` (bit 4).
    pub const ELEVATION: u16 = 0x0010;
    /// Mask of `azimuth` (bit 5).
    pub const AZIMUTH: u16 = 0x0020;
    /// Mask of `health` (bit 6).
    pub const HEALTH: u16 = 0x0040;
    /// Mask of `flags` (bits 0..=6).
    pub const FLAGS: u16 = 0x007F;
    /// Mask of `reserved` (bits 7..=15).
    pub const RESERVED: u16 = 0xFF80;

    /// Time of week valid. (bit 0)
    pub const fn tow(self) -> bool {
        self.0 & Self::TOW != 0
    }

    /// Sets or clears `tow` (bit 0).
    pub fn set_tow(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW;
        } else {
            self.0 &= !Self::TOW;
        }
    }

    /// Week number valid. (bit 1)
    pub const fn week_number(self) -> bool {
        self.0 & Self::WEEK_NUMBER != 0
    }

    /// Sets or clears `week_number` (bit 1).
    pub fn set_week_number(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER;
        } else {
            self.0 &= !Self::WEEK_NUMBER;
        }
    }

    /// Constellation id valid. (bit 2)
    pub const fn gnss_id(self) -> bool {
        self.0 & Self::GNSS_ID != 0
    }

    /// Sets or clears `gnss_id` (bit 2).
    pub fn set_gnss_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_ID;
        } else {
            self.0 &= !Self::GNSS_ID;
        }
    }

    /// Satellite id valid. (bit 3)
    pub const fn satellite_id(self) -> bool {
        self.0 & Self::SATELLITE_ID != 0
    }

    /// Sets or clears `satellite_id` (bit 3).
    pub fn set_satellite_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::SATELLITE_ID;
        } else {
            self.0 &= !Self::SATELLITE_ID;
        }
    }

    /// Elevation valid. (bit 4)
    pub const fn elevation(self) -> bool {
        self.0 & Self::ELEVATION != 0
    }

    /// Sets or clears `elevation` (bit 4).
    pub fn set_elevation(&mut self, v: bool) {
        if v {
            self.0 |= Self::ELEVATION;
        } else {
            self.0 &= !Self::ELEVATION;
        }
    }

    /// Azimuth valid. (bit 5)
    pub const fn azimuth(self) -> bool {
        self.0 & Self::AZIMUTH != 0
    }

    /// Sets or clears `azimuth` (bit 5).
    pub fn set_azimuth(&mut self, v: bool) {
        if v {
            self.0 |= Self::AZIMUTH;
        } else {
            self.0 &= !Self::AZIMUTH;
        }
    }

    /// Health valid. (bit 6)
    pub const fn health(self) -> bool {
        self.0 & Self::HEALTH != 0
    }

    /// Sets or clears `health` (bit 6).
    pub fn set_health(&mut self, v: bool) {
        if v {
            self.0 |= Self::HEALTH;
        } else {
            self.0 &= !Self::HEALTH;
        }
    }

    /// All valid flags (the manual's 'flags 0-6' entry). (bits 0..=6)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=6); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manual. Reserved. (bits 7..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 7
    }

    /// Sets `reserved` (bits 7..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 7) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssSatelliteStatusValidFlags {
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
impl crate::json_read::FromJson for GnssSatelliteStatusValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// SBAS information valid flags. Which parameters of the SBAS information field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssSbasInfoValidFlags(pub u16);

impl GnssSbasInfoValidFlags {
    /// Mask of `tow` (bit 0).
    pub const TOW: u16 = 0x0001;
    /// Mask of `week_number` (bit 1).
    pub const WEEK_NUMBER: u16 = 0x0002;
    /// Mask of `sbas_system` (bit 2).
    pub const SBAS_SYSTEM: u16 = 0x0004;
    /// Mask of `sbas_id` (bit 3).
    pub const SBAS_ID: u16 = 0x0008;
    /// Mask of `count` (bit 4).
    pub const COUNT: u16 = 0x0010;
    /// Mask of `sbas_status` (bit 5).
    pub const SBAS_STATUS: u16 = 0x0020;
    /// Mask of `flags` (bits 0..=5).
    pub const FLAGS: u16 = 0x003F;
    /// Mask of `reserved` (bits 6..=15).
    pub const RESERVED: u16 = 0xFFC0;

    /// Time of week valid. (bit 0)
    pub const fn tow(self) -> bool {
        self.0 & Self::TOW != 0
    }

    /// Sets or clears `tow` (bit 0).
    pub fn set_tow(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW;
        } else {
            self.0 &= !Self::TOW;
        }
    }

    /// Week number valid. (bit 1)
    pub const fn week_number(self) -> bool {
        self.0 & Self::WEEK_NUMBER != 0
    }

    /// Sets or clears `week_number` (bit 1).
    pub fn set_week_number(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER;
        } else {
            self.0 &= !Self::WEEK_NUMBER;
        }
    }

    /// SBAS system valid. (bit 2)
    pub const fn sbas_system(self) -> bool {
        self.0 & Self::SBAS_SYSTEM != 0
    }

    /// Sets or clears `sbas_system` (bit 2).
    pub fn set_sbas_system(&mut self, v: bool) {
        if v {
            self.0 |= Self::SBAS_SYSTEM;
        } else {
            self.0 &= !Self::SBAS_SYSTEM;
        }
    }

    /// SBAS satellite id valid. (bit 3)
    pub const fn sbas_id(self) -> bool {
        self.0 & Self::SBAS_ID != 0
    }

    /// Sets or clears `sbas_id` (bit 3).
    pub fn set_sbas_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::SBAS_ID;
        } else {
            self.0 &= !Self::SBAS_ID;
        }
    }

    /// Number of corrections valid. (bit 4)
    pub const fn count(self) -> bool {
        self.0 & Self::COUNT != 0
    }

    /// Sets or clears `count` (bit 4).
    pub fn set_count(&mut self, v: bool) {
        if v {
            self.0 |= Self::COUNT;
        } else {
            self.0 &= !Self::COUNT;
        }
    }

    /// SBAS status valid. (bit 5)
    pub const fn sbas_status(self) -> bool {
        self.0 & Self::SBAS_STATUS != 0
    }

    /// Sets or clears `sbas_status` (bit 5).
    pub fn set_sbas_status(&mut self, v: bool) {
        if v {
            self.0 |= Self::SBAS_STATUS;
        } else {
            self.0 &= !Self::SBAS_STATUS;
        }
    }

    /// All flags. (bits 0..=5)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=5); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manual. Reserved. (bits 6..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 6
    }

    /// Sets `reserved` (bits 6..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 6) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssSbasInfoValidFlags {
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
impl crate::json_read::FromJson for GnssSbasInfoValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// SBAS status. Status of the SBAS service.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssSbasStatus(pub u8);

impl GnssSbasStatus {
    /// Mask of `range_available` (bit 0).
    pub const RANGE_AVAILABLE: u8 = 0x01;
    /// Mask of `corrections_available` (bit 1).
    pub const CORRECTIONS_AVAILABLE: u8 = 0x02;
    /// Mask of `integrity_available` (bit 2).
    pub const INTEGRITY_AVAILABLE: u8 = 0x04;
    /// Mask of `test_mode` (bit 3).
    pub const TEST_MODE: u8 = 0x08;
    /// Mask of `reserved` (bits 4..=7).
    pub const RESERVED: u8 = 0xF0;

    /// SBAS ranging available. (bit 0)
    pub const fn range_available(self) -> bool {
        self.0 & Self::RANGE_AVAILABLE != 0
    }

    /// Sets or clears `range_available` (bit 0).
    pub fn set_range_available(&mut self, v: bool) {
        if v {
            self.0 |= Self::RANGE_AVAILABLE;
        } else {
            self.0 &= !Self::RANGE_AVAILABLE;
        }
    }

    /// SBAS corrections available. (bit 1)
    pub const fn corrections_available(self) -> bool {
        self.0 & Self::CORRECTIONS_AVAILABLE != 0
    }

    /// Sets or clears `corrections_available` (bit 1).
    pub fn set_corrections_available(&mut self, v: bool) {
        if v {
            self.0 |= Self::CORRECTIONS_AVAILABLE;
        } else {
            self.0 &= !Self::CORRECTIONS_AVAILABLE;
        }
    }

    /// SBAS integrity information available. (bit 2)
    pub const fn integrity_available(self) -> bool {
        self.0 & Self::INTEGRITY_AVAILABLE != 0
    }

    /// Sets or clears `integrity_available` (bit 2).
    pub fn set_integrity_available(&mut self, v: bool) {
        if v {
            self.0 |= Self::INTEGRITY_AVAILABLE;
        } else {
            self.0 &= !Self::INTEGRITY_AVAILABLE;
        }
    }

    /// SBAS is in test mode. (bit 3)
    pub const fn test_mode(self) -> bool {
        self.0 & Self::TEST_MODE != 0
    }

    /// Sets or clears `test_mode` (bit 3).
    pub fn set_test_mode(&mut self, v: bool) {
        if v {
            self.0 |= Self::TEST_MODE;
        } else {
            self.0 &= !Self::TEST_MODE;
        }
    }

    /// Not named by the manual. Reserved. (bits 4..=7)
    pub const fn reserved(self) -> u8 {
        (self.0 & Self::RESERVED) >> 4
    }

    /// Sets `reserved` (bits 4..=7); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 4) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssSbasStatus {
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
impl crate::json_read::FromJson for GnssSbasStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// SBAS system. Satellite-based augmentation system the receiver is using.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssSbasSystem(pub u8);

impl GnssSbasSystem {
    /// Unknown.
    pub const UNKNOWN: Self = Self(0);
    /// WAAS (North America).
    pub const WAAS: Self = Self(1);
    /// EGNOS (Europe).
    pub const EGNOS: Self = Self(2);
    /// MSAS (Japan).
    pub const MSAS: Self = Self(3);
    /// GAGAN (India).
    pub const GAGAN: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unknown"),
            1 => Some("waas"),
            2 => Some("egnos"),
            3 => Some("msas"),
            4 => Some("gagan"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unknown" => Some(Self::UNKNOWN),
            "waas" => Some(Self::WAAS),
            "egnos" => Some(Self::EGNOS),
            "msas" => Some(Self::MSAS),
            "gagan" => Some(Self::GAGAN),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssSbasSystem {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssSbasSystem({} {})", self.0, name),
            None => write!(f, "GnssSbasSystem({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssSbasSystem {
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
impl crate::json_read::FromJson for GnssSbasSystem {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS signal identifier. The constellation, frequency band and code/channel component of one observation.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssSignalId(pub u8);

impl GnssSignalId {
    /// Unknown or unspecified signal.
    pub const UNKNOWN: Self = Self(0);
    /// GPS L1 C/A.
    pub const GPS_L1CA: Self = Self(1);
    /// GPS L1 P.
    pub const GPS_L1P: Self = Self(2);
    /// GPS L1 Z-tracking.
    pub const GPS_L1Z: Self = Self(3);
    /// GPS L2 C/A.
    pub const GPS_L2CA: Self = Self(4);
    /// GPS L2 P.
    pub const GPS_L2P: Self = Self(5);
    /// GPS L2 Z-tracking.
    pub const GPS_L2Z: Self = Self(6);
    /// GPS L2C long code (L).
    pub const GPS_L2CL: Self = Self(7);
    /// GPS L2C medium code (M).
    pub const GPS_L2CM: Self = Self(8);
    /// GPS L2C combined M+L.
    pub const GPS_L2CML: Self = Self(9);
    /// GPS L5 I (data).
    pub const GPS_L5I: Self = Self(10);
    /// GPS L5 Q (pilot).
    pub const GPS_L5Q: Self = Self(11);
    /// GPS L5 combined I+Q.
    pub const GPS_L5IQ: Self = Self(12);
    /// GPS L1C data (D).
    pub const GPS_L1CD: Self = Self(13);
    /// GPS L1C pilot (P).
    pub const GPS_L1CP: Self = Self(14);
    /// GPS L1C combined D+P.
    pub const GPS_L1CDP: Self = Self(15);
    /// GLONASS G1 C/A.
    pub const GLONASS_G1CA: Self = Self(32);
    /// GLONASS G1 P.
    pub const GLONASS_G1P: Self = Self(33);
    /// GLONASS G2 C/A.
    pub const GLONASS_G2C: Self = Self(34);
    /// GLONASS G2 P.
    pub const GLONASS_G2P: Self = Self(35);
    /// Galileo E1 C (pilot).
    pub const GALILEO_E1C: Self = Self(64);
    /// Galileo E1 A (PRS).
    pub const GALILEO_E1A: Self = Self(65);
    /// Galileo E1 B (data).
    pub const GALILEO_E1B: Self = Self(66);
    /// Galileo E1 combined B+C.
    pub const GALILEO_E1BC: Self = Self(67);
    /// Galileo E1 combined A+B+C.
    pub const GALILEO_E1ABC: Self = Self(68);
    /// Galileo E6 C (pilot).
    pub const GALILEO_E6C: Self = Self(69);
    /// Galileo E6 A (PRS).
    pub const GALILEO_E6A: Self = Self(70);
    /// Galileo E6 B (data).
    pub const GALILEO_E6B: Self = Self(71);
    /// Galileo E6 combined B+C.
    pub const GALILEO_E6BC: Self = Self(72);
    /// Galileo E6 combined A+B+C.
    pub const GALILEO_E6ABC: Self = Self(73);
    /// Galileo E5b I (data).
    pub const GALILEO_E5BI: Self = Self(74);
    /// Galileo E5b Q (pilot).
    pub const GALILEO_E5BQ: Self = Self(75);
    /// Galileo E5b combined I+Q.
    pub const GALILEO_E5BIQ: Self = Self(76);
    /// Galileo E5 AltBOC (E5a+E5b) I (data).
    pub const GALILEO_E5ABI: Self = Self(77);
    /// Galileo E5 AltBOC (E5a+E5b) Q (pilot).
    pub const GALILEO_E5ABQ: Self = Self(78);
    /// Galileo E5 AltBOC (E5a+E5b) combined I+Q.
    pub const GALILEO_E5ABIQ: Self = Self(79);
    /// Galileo E5a I (data).
    pub const GALILEO_E5AI: Self = Self(80);
    /// Galileo E5a Q (pilot).
    pub const GALILEO_E5AQ: Self = Self(81);
    /// Galileo E5a combined I+Q.
    pub const GALILEO_E5AIQ: Self = Self(82);
    /// SBAS L1 C/A.
    pub const SBAS_L1CA: Self = Self(96);
    /// SBAS L5 I (data).
    pub const SBAS_L5I: Self = Self(97);
    /// SBAS L5 Q (pilot).
    pub const SBAS_L5Q: Self = Self(98);
    /// SBAS L5 combined I+Q.
    pub const SBAS_L5IQ: Self = Self(99);
    /// QZSS L1 C/A.
    pub const QZSS_L1CA: Self = Self(128);
    /// QZSS LEX short code (S).
    pub const QZSS_LEXS: Self = Self(129);
    /// QZSS LEX long code (L).
    pub const QZSS_LEXL: Self = Self(130);
    /// QZSS LEX combined S+L.
    pub const QZSS_LEXSL: Self = Self(131);
    /// QZSS L2C medium code (M).
    pub const QZSS_L2CM: Self = Self(132);
    /// QZSS L2C long code (L).
    pub const QZSS_L2CL: Self = Self(133);
    /// QZSS L2C combined M+L.
    pub const QZSS_L2CML: Self = Self(134);
    /// QZSS L5 I (data).
    pub const QZSS_L5I: Self = Self(135);
    /// QZSS L5 Q (pilot).
    pub const QZSS_L5Q: Self = Self(136);
    /// QZSS L5 combined I+Q.
    pub const QZSS_L5IQ: Self = Self(137);
    /// QZSS L1C data (D).
    pub const QZSS_L1CD: Self = Self(138);
    /// QZSS L1C pilot (P).
    pub const QZSS_L1CP: Self = Self(139);
    /// QZSS L1C combined D+P.
    pub const QZSS_L1CDP: Self = Self(140);
    /// BeiDou B1 I.
    pub const BEIDOU_B1I: Self = Self(160);
    /// BeiDou B1 Q.
    pub const BEIDOU_B1Q: Self = Self(161);
    /// BeiDou B1 combined I+Q.
    pub const BEIDOU_B1IQ: Self = Self(162);
    /// BeiDou B3 I.
    pub const BEIDOU_B3I: Self = Self(163);
    /// BeiDou B3 Q.
    pub const BEIDOU_B3Q: Self = Self(164);
    /// BeiDou B3 combined I+Q.
    pub const BEIDOU_B3IQ: Self = Self(165);
    /// BeiDou B2 I.
    pub const BEIDOU_B2I: Self = Self(166);
    /// BeiDou B2 Q.
    pub const BEIDOU_B2Q: Self = Self(167);
    /// BeiDou B2 combined I+Q.
    pub const BEIDOU_B2IQ: Self = Self(168);
    /// BeiDou B2a.
    pub const BEIDOU_B2A: Self = Self(169);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unknown"),
            1 => Some("gps_l1ca"),
            2 => Some("gps_l1p"),
            3 => Some("gps_l1z"),
            4 => Some("gps_l2ca"),
            5 => Some("gps_l2p"),
            6 => Some("gps_l2z"),
            7 => Some("gps_l2cl"),
            8 => Some("gps_l2cm"),
            9 => Some("gps_l2cml"),
            10 => Some("gps_l5i"),
            11 => Some("gps_l5q"),
            12 => Some("gps_l5iq"),
            13 => Some("gps_l1cd"),
            14 => Some("gps_l1cp"),
            15 => Some("gps_l1cdp"),
            32 => Some("glonass_g1ca"),
            33 => Some("glonass_g1p"),
            34 => Some("glonass_g2c"),
            35 => Some("glonass_g2p"),
            64 => Some("galileo_e1c"),
            65 => Some("galileo_e1a"),
            66 => Some("galileo_e1b"),
            67 => Some("galileo_e1bc"),
            68 => Some("galileo_e1abc"),
            69 => Some("galileo_e6c"),
            70 => Some("galileo_e6a"),
            71 => Some("galileo_e6b"),
            72 => Some("galileo_e6bc"),
            73 => Some("galileo_e6abc"),
            74 => Some("galileo_e5bi"),
            75 => Some("galileo_e5bq"),
            76 => Some("galileo_e5biq"),
            77 => Some("galileo_e5abi"),
            78 => Some("galileo_e5abq"),
            79 => Some("galileo_e5abiq"),
            80 => Some("galileo_e5ai"),
            81 => Some("galileo_e5aq"),
            82 => Some("galileo_e5aiq"),
            96 => Some("sbas_l1ca"),
            97 => Some("sbas_l5i"),
            98 => Some("sbas_l5q"),
            99 => Some("sbas_l5iq"),
            128 => Some("qzss_l1ca"),
            129 => Some("qzss_lexs"),
            130 => Some("qzss_lexl"),
            131 => Some("qzss_lexsl"),
            132 => Some("qzss_l2cm"),
            133 => Some("qzss_l2cl"),
            134 => Some("qzss_l2cml"),
            135 => Some("qzss_l5i"),
            136 => Some("qzss_l5q"),
            137 => Some("qzss_l5iq"),
            138 => Some("qzss_l1cd"),
            139 => Some("qzss_l1cp"),
            140 => Some("qzss_l1cdp"),
            160 => Some("beidou_b1i"),
            161 => Some("beidou_b1q"),
            162 => Some("beidou_b1iq"),
            163 => Some("beidou_b3i"),
            164 => Some("beidou_b3q"),
            165 => Some("beidou_b3iq"),
            166 => Some("beidou_b2i"),
            167 => Some("beidou_b2q"),
            168 => Some("beidou_b2iq"),
            169 => Some("beidou_b2a"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unknown" => Some(Self::UNKNOWN),
            "gps_l1ca" => Some(Self::GPS_L1CA),
            "gps_l1p" => Some(Self::GPS_L1P),
            "gps_l1z" => Some(Self::GPS_L1Z),
            "gps_l2ca" => Some(Self::GPS_L2CA),
            "gps_l2p" => Some(Self::GPS_L2P),
            "gps_l2z" => Some(Self::GPS_L2Z),
            "gps_l2cl" => Some(Self::GPS_L2CL),
            "gps_l2cm" => Some(Self::GPS_L2CM),
            "gps_l2cml" => Some(Self::GPS_L2CML),
            "gps_l5i" => Some(Self::GPS_L5I),
            "gps_l5q" => Some(Self::GPS_L5Q),
            "gps_l5iq" => Some(Self::GPS_L5IQ),
            "gps_l1cd" => Some(Self::GPS_L1CD),
            "gps_l1cp" => Some(Self::GPS_L1CP),
            "gps_l1cdp" => Some(Self::GPS_L1CDP),
            "glonass_g1ca" => Some(Self::GLONASS_G1CA),
            "glonass_g1p" => Some(Self::GLONASS_G1P),
            "glonass_g2c" => Some(Self::GLONASS_G2C),
            "glonass_g2p" => Some(Self::GLONASS_G2P),
            "galileo_e1c" => Some(Self::GALILEO_E1C),
            "galileo_e1a" => Some(Self::GALILEO_E1A),
            "galileo_e1b" => Some(Self::GALILEO_E1B),
            "galileo_e1bc" => Some(Self::GALILEO_E1BC),
            "galileo_e1abc" => Some(Self::GALILEO_E1ABC),
            "galileo_e6c" => Some(Self::GALILEO_E6C),
            "galileo_e6a" => Some(Self::GALILEO_E6A),
            "galileo_e6b" => Some(Self::GALILEO_E6B),
            "galileo_e6bc" => Some(Self::GALILEO_E6BC),
            "galileo_e6abc" => Some(Self::GALILEO_E6ABC),
            "galileo_e5bi" => Some(Self::GALILEO_E5BI),
            "galileo_e5bq" => Some(Self::GALILEO_E5BQ),
            "galileo_e5biq" => Some(Self::GALILEO_E5BIQ),
            "galileo_e5abi" => Some(Self::GALILEO_E5ABI),
            "galileo_e5abq" => Some(Self::GALILEO_E5ABQ),
            "galileo_e5abiq" => Some(Self::GALILEO_E5ABIQ),
            "galileo_e5ai" => Some(Self::GALILEO_E5AI),
            "galileo_e5aq" => Some(Self::GALILEO_E5AQ),
            "galileo_e5aiq" => Some(Self::GALILEO_E5AIQ),
            "sbas_l1ca" => Some(Self::SBAS_L1CA),
            "sbas_l5i" => Some(Self::SBAS_L5I),
            "sbas_l5q" => Some(Self::SBAS_L5Q),
            "sbas_l5iq" => Some(Self::SBAS_L5IQ),
            "qzss_l1ca" => Some(Self::QZSS_L1CA),
            "qzss_lexs" => Some(Self::QZSS_LEXS),
            "qzss_lexl" => Some(Self::QZSS_LEXL),
            "qzss_lexsl" => Some(Self::QZSS_LEXSL),
            "qzss_l2cm" => Some(Self::QZSS_L2CM),
            "qzss_l2cl" => Some(Self::QZSS_L2CL),
            "qzss_l2cml" => Some(Self::QZSS_L2CML),
            "qzss_l5i" => Some(Self::QZSS_L5I),
            "qzss_l5q" => Some(Self::QZSS_L5Q),
            "qzss_l5iq" => Some(Self::QZSS_L5IQ),
            "qzss_l1cd" => Some(Self::QZSS_L1CD),
            "qzss_l1cp" => Some(Self::QZSS_L1CP),
            "qzss_l1cdp" => Some(Self::QZSS_L1CDP),
            "beidou_b1i" => Some(Self::BEIDOU_B1I),
            "beidou_b1q" => Some(Self::BEIDOU_B1Q),
            "beidou_b1iq" => Some(Self::BEIDOU_B1IQ),
            "beidou_b3i" => Some(Self::BEIDOU_B3I),
            "beidou_b3q" => Some(Self::BEIDOU_B3Q),
            "beidou_b3iq" => Some(Self::BEIDOU_B3IQ),
            "beidou_b2i" => Some(Self::BEIDOU_B2I),
            "beidou_b2q" => Some(Self::BEIDOU_B2Q),
            "beidou_b2iq" => Some(Self::BEIDOU_B2IQ),
            "beidou_b2a" => Some(Self::BEIDOU_B2A),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssSignalId {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssSignalId({} {})", self.0, name),
            None => write!(f, "GnssSignalId({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssSignalId {
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
impl crate::json_read::FromJson for GnssSignalId {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS raw observation signal quality. Tracking state of the signal an observation comes from.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GnssSignalQuality(pub u8);

impl GnssSignalQuality {
    /// No signal.
    pub const NONE: Self = Self(0);
    /// Searching for the signal.
    pub const SEARCHING: Self = Self(1);
    /// Signal acquired.
    pub const ACQUIRED: Self = Self(2);
    /// Signal detected but unusable.
    pub const UNUSABLE: Self = Self(3);
    /// Time locked.
    pub const TIME_LOCKED: Self = Self(4);
    /// Fully locked.
    pub const FULLY_LOCKED: Self = Self(5);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("searching"),
            2 => Some("acquired"),
            3 => Some("unusable"),
            4 => Some("time_locked"),
            5 => Some("fully_locked"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "searching" => Some(Self::SEARCHING),
            "acquired" => Some(Self::ACQUIRED),
            "unusable" => Some(Self::UNUSABLE),
            "time_locked" => Some(Self::TIME_LOCKED),
            "fully_locked" => Some(Self::FULLY_LOCKED),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GnssSignalQuality {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GnssSignalQuality({} {})", self.0, name),
            None => write!(f, "GnssSignalQuality({})", self.0),
        }
    }
}

impl crate::wire::Wire for GnssSignalQuality {
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
impl crate::json_read::FromJson for GnssSignalQuality {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Space vehicle flags. Use and health of one space vehicle.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssSvFlags(pub u16);

impl GnssSvFlags {
    /// Mask of `used_for_navigation` (bit 0).
    pub const USED_FOR_NAVIGATION: u16 = 0x0001;
    /// Mask of `healthy` (bit 1).
    pub const HEALTHY: u16 = 0x0002;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// The SV is used in the navigation solution. (bit 0)
    pub const fn used_for_navigation(self) -> bool {
        self.0 & Self::USED_FOR_NAVIGATION != 0
    }

    /// Sets or clears `used_for_navigation` (bit 0).
    pub fn set_used_for_navigation(&mut self, v: bool) {
        if v {
            self.0 |= Self::USED_FOR_NAVIGATION;
        } else {
            self.0 &= !Self::USED_FOR_NAVIGATION;
        }
    }

    /// The SV is healthy. (bit 1)
    pub const fn healthy(self) -> bool {
        self.0 & Self::HEALTHY != 0
    }

    /// Sets or clears `healthy` (bit 1).
    pub fn set_healthy(&mut self, v: bool) {
        if v {
            self.0 |= Self::HEALTHY;
        } else {
            self.0 &= !Self::HEALTHY;
        }
    }

    /// Not named by the manual. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssSvFlags {
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
impl crate::json_read::FromJson for GnssSvFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Space vehicle information valid flags. Which parameters of a space vehicle information entry are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssSvInfoValidFlags(pub u16);

impl GnssSvInfoValidFlags {
    /// Mask of `channel` (bit 0).
    pub const CHANNEL: u16 = 0x0001;
    /// Mask of `sv_id` (bit 1).
    pub const SV_ID: u16 = 0x0002;
    /// Mask of `reserved_2` (bit 2).
    pub const RESERVED_2: u16 = 0x0004;
    /// Mask of `carrier_to_noise_ratio` (bit 3).
    pub const CARRIER_TO_NOISE_RATIO: u16 = 0x0008;
    /// Mask of `azimuth` (bit 4).
    pub const AZIMUTH: u16 = 0x0010;
    /// Mask of `elevation` (bit 5).
    pub const ELEVATION: u16 = 0x0020;
    /// Mask of `sv_flags` (bit 6).
    pub const SV_FLAGS: u16 = 0x0040;
    /// Mask of `reserved` (bits 7..=15).
    pub const RESERVED: u16 = 0xFF80;

    /// Channel valid. (bit 0)
    pub const fn channel(self) -> bool {
        self.0 & Self::CHANNEL != 0
    }

    /// Sets or clears `channel` (bit 0).
    pub fn set_channel(&mut self, v: bool) {
        if v {
            self.0 |= Self::CHANNEL;
        } else {
            self.0 &= !Self::CHANNEL;
        }
    }

    /// Space vehicle id valid. (bit 1)
    pub const fn sv_id(self) -> bool {
        self.0 & Self::SV_ID != 0
    }

    /// Sets or clears `sv_id` (bit 1).
    pub fn set_sv_id(&mut self, v: bool) {
        if v {
            self.0 |= Self::SV_ID;
        } else {
            self.0 &= !Self::SV_ID;
        }
    }

    /// Not named by the manual (its list skips 0x0004). Reserved. (bit 2)
    pub const fn reserved_2(self) -> bool {
        self.0 & Self::RESERVED_2 != 0
    }

    /// Sets or clears `reserved_2` (bit 2).
    pub fn set_reserved_2(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_2;
        } else {
            self.0 &= !Self::RESERVED_2;
        }
    }

    /// Carrier to noise ratio valid. (bit 3)
    pub const fn carrier_to_noise_ratio(self) -> bool {
        self.0 & Self::CARRIER_TO_NOISE_RATIO != 0
    }

    /// Sets or clears `carrier_to_noise_ratio` (bit 3).
    pub fn set_carrier_to_noise_ratio(&mut self, v: bool) {
        if v {
            self.0 |= Self::CARRIER_TO_NOISE_RATIO;
        } else {
            self.0 &= !Self::CARRIER_TO_NOISE_RATIO;
        }
    }

    /// Azimuth valid. (bit 4)
    pub const fn azimuth(self) -> bool {
        self.0 & Self::AZIMUTH != 0
    }

    /// Sets or clears `azimuth` (bit 4).
    pub fn set_azimuth(&mut self, v: bool) {
        if v {
            self.0 |= Self::AZIMUTH;
        } else {
            self.0 &= !Self::AZIMUTH;
        }
    }

    /// Elevation valid. (bit 5)
    pub const fn elevation(self) -> bool {
        self.0 & Self::ELEVATION != 0
    }

    /// Sets or clears `elevation` (bit 5).
    pub fn set_elevation(&mut self, v: bool) {
        if v {
            self.0 |= Self::ELEVATION;
        } else {
            self.0 &= !Self::ELEVATION;
        }
    }

    /// Space vehicle flags valid. (bit 6)
    pub const fn sv_flags(self) -> bool {
        self.0 & Self::SV_FLAGS != 0
    }

    /// Sets or clears `sv_flags` (bit 6).
    pub fn set_sv_flags(&mut self, v: bool) {
        if v {
            self.0 |= Self::SV_FLAGS;
        } else {
            self.0 &= !Self::SV_FLAGS;
        }
    }

    /// Not named by the manual. Reserved. (bits 7..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 7
    }

    /// Sets `reserved` (bits 7..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 7) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssSvInfoValidFlags {
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
impl crate::json_read::FromJson for GnssSvInfoValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS UTC time valid flags (CV7). Validity of a CV7 GNSS UTC time field.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssUtcTimeValidFlagsCv7(pub u16);

impl GnssUtcTimeValidFlagsCv7 {
    /// Mask of `gnss_date_time` (bit 0).
    pub const GNSS_DATE_TIME: u16 = 0x0001;
    /// Mask of `leap_seconds_known` (bit 1).
    pub const LEAP_SECONDS_KNOWN: u16 = 0x0002;
    /// Mask of `flags` (bits 0..=1).
    pub const FLAGS: u16 = 0x0003;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// Date and time valid. (bit 0)
    pub const fn gnss_date_time(self) -> bool {
        self.0 & Self::GNSS_DATE_TIME != 0
    }

    /// Sets or clears `gnss_date_time` (bit 0).
    pub fn set_gnss_date_time(&mut self, v: bool) {
        if v {
            self.0 |= Self::GNSS_DATE_TIME;
        } else {
            self.0 &= !Self::GNSS_DATE_TIME;
        }
    }

    /// The GPS-UTC leap second offset is known, so the UTC time is exact. (bit 1)
    pub const fn leap_seconds_known(self) -> bool {
        self.0 & Self::LEAP_SECONDS_KNOWN != 0
    }

    /// Sets or clears `leap_seconds_known` (bit 1).
    pub fn set_leap_seconds_known(&mut self, v: bool) {
        if v {
            self.0 |= Self::LEAP_SECONDS_KNOWN;
        } else {
            self.0 &= !Self::LEAP_SECONDS_KNOWN;
        }
    }

    /// All flags. (bits 0..=1)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=1); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manual. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssUtcTimeValidFlagsCv7 {
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
impl crate::json_read::FromJson for GnssUtcTimeValidFlagsCv7 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS UTC time valid flags (GX5-45). Validity of the GX5-45 GNSS UTC time field.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GnssUtcTimeValidFlagsGx5(pub u16);

impl GnssUtcTimeValidFlagsGx5 {
    /// Mask of `date_valid` (bit 0).
    pub const DATE_VALID: u16 = 0x0001;
    /// Mask of `time_valid` (bit 1).
    pub const TIME_VALID: u16 = 0x0002;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// Date valid. (bit 0)
    pub const fn date_valid(self) -> bool {
        self.0 & Self::DATE_VALID != 0
    }

    /// Sets or clears `date_valid` (bit 0).
    pub fn set_date_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::DATE_VALID;
        } else {
            self.0 &= !Self::DATE_VALID;
        }
    }

    /// Time valid. (bit 1)
    pub const fn time_valid(self) -> bool {
        self.0 & Self::TIME_VALID != 0
    }

    /// Sets or clears `time_valid` (bit 1).
    pub fn set_time_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIME_VALID;
        } else {
            self.0 &= !Self::TIME_VALID;
        }
    }

    /// Not named by the manual. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GnssUtcTimeValidFlagsGx5 {
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
impl crate::json_read::FromJson for GnssUtcTimeValidFlagsGx5 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO behavior, read according to the feature. The behavior byte's meaning depends on the feature: the same number names a different behavior per feature (2 is GPIO_OUTPUT_LOW for GPIO, PPS_OUTPUT for PPS, ENCODER_B for ENCODER, TIMESTAMP_FALLING for TIMESTAMP). Every member is one u8.
///
/// A union: the member is chosen by the value of an earlier selector parameter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GpioBehavior {
    /// Feature UNUSED: behavior 0.
    Unused(crate::types::GpioBehaviorUnused),
    /// Feature GPIO: GPIO_INPUT / GPIO_OUTPUT_LOW / GPIO_OUTPUT_HIGH.
    Gpio(crate::types::GpioBehaviorIo),
    /// Feature PPS: PPS_INPUT / PPS_OUTPUT.
    Pps(crate::types::GpioBehaviorPps),
    /// Feature ENCODER: ENCODER_A / ENCODER_B.
    Encoder(crate::types::GpioBehaviorEncoder),
    /// Feature TIMESTAMP: TIMESTAMP_RISING / _FALLING / _EITHER.
    Timestamp(crate::types::GpioBehaviorTimestamp),
    /// Feature UART: UART_PORT2_TX/RX, UART_PORT3_TX/RX.
    Uart(crate::types::GpioBehaviorUart),
}

impl GpioBehavior {
    /// The first member with zero values.
    pub const ZERO: Self =
        Self::Unused(<crate::types::GpioBehaviorUnused as crate::wire::Wire>::ZERO);

    /// Selector value of this member.
    pub fn selector_value(&self) -> u8 {
        match self {
            Self::Unused(_) => 0,
            Self::Gpio(_) => 1,
            Self::Pps(_) => 2,
            Self::Encoder(_) => 3,
            Self::Timestamp(_) => 4,
            Self::Uart(_) => 5,
        }
    }

    /// Reads the member selected by `selector`.
    pub fn decode_selected(
        r: &mut crate::wire::Reader<'_>,
        selector: u8,
    ) -> Result<Self, crate::error::DecodeError> {
        match selector {
            0 => {
                <crate::types::GpioBehaviorUnused as crate::wire::Wire>::decode(r).map(Self::Unused)
            }
            1 => <crate::types::GpioBehaviorIo as crate::wire::Wire>::decode(r).map(Self::Gpio),
            2 => <crate::types::GpioBehaviorPps as crate::wire::Wire>::decode(r).map(Self::Pps),
            3 => <crate::types::GpioBehaviorEncoder as crate::wire::Wire>::decode(r)
                .map(Self::Encoder),
            4 => <crate::types::GpioBehaviorTimestamp as crate::wire::Wire>::decode(r)
                .map(Self::Timestamp),
            5 => <crate::types::GpioBehaviorUart as crate::wire::Wire>::decode(r).map(Self::Uart),
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
            Self::Unused(v) => crate::wire::Wire::encode(v, w),
            Self::Gpio(v) => crate::wire::Wire::encode(v, w),
            Self::Pps(v) => crate::wire::Wire::encode(v, w),
            Self::Encoder(v) => crate::wire::Wire::encode(v, w),
            Self::Timestamp(v) => crate::wire::Wire::encode(v, w),
            Self::Uart(v) => crate::wire::Wire::encode(v, w),
        }
    }

    /// Writes the member's struct, or `null` for a member without data.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Unused(v) => crate::wire::Wire::write_json(v, w),
            Self::Gpio(v) => crate::wire::Wire::write_json(v, w),
            Self::Pps(v) => crate::wire::Wire::write_json(v, w),
            Self::Encoder(v) => crate::wire::Wire::write_json(v, w),
            Self::Timestamp(v) => crate::wire::Wire::write_json(v, w),
            Self::Uart(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the member selected by `selector`.
    #[cfg(feature = "std")]
    pub fn from_json_selected(
        v: &crate::json_read::Json,
        selector: u8,
    ) -> Result<Self, crate::json_read::JsonError> {
        match selector {
            0 => <crate::types::GpioBehaviorUnused as crate::json_read::FromJson>::from_json(v)
                .map(Self::Unused),
            1 => <crate::types::GpioBehaviorIo as crate::json_read::FromJson>::from_json(v)
                .map(Self::Gpio),
            2 => <crate::types::GpioBehaviorPps as crate::json_read::FromJson>::from_json(v)
                .map(Self::Pps),
            3 => <crate::types::GpioBehaviorEncoder as crate::json_read::FromJson>::from_json(v)
                .map(Self::Encoder),
            4 => <crate::types::GpioBehaviorTimestamp as crate::json_read::FromJson>::from_json(v)
                .map(Self::Timestamp),
            5 => <crate::types::GpioBehaviorUart as crate::json_read::FromJson>::from_json(v)
                .map(Self::Uart),
            value => Err(crate::json_read::JsonError::new(std::format!(
                "no member for selector value {value}"
            ))),
        }
    }
}

/// GpioBehaviorEncoder.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioBehaviorEncoder {
    /// Quadrature channel A or B.
    pub behavior: crate::types::GpioEncoderBehavior,
}

impl Default for GpioBehaviorEncoder {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioBehaviorEncoder {
    const ZERO: Self = Self {
        behavior: <crate::types::GpioEncoderBehavior as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_behavior = <crate::types::GpioEncoderBehavior as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("behavior"))?;
        Ok(Self {
            behavior: p_behavior,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.behavior;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("behavior"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.behavior;
        crate::json::key(w, &mut first, "behavior")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioBehaviorEncoder {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["behavior"])?;
        let p_behavior = o.req(
            "behavior",
            <crate::types::GpioEncoderBehavior as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            behavior: p_behavior,
        })
    }
}

/// GpioBehaviorIo.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioBehaviorIo {
    /// Input, or output with its initial state.
    pub behavior: crate::types::GpioIoBehavior,
}

impl Default for GpioBehaviorIo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioBehaviorIo {
    const ZERO: Self = Self {
        behavior: <crate::types::GpioIoBehavior as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_behavior = <crate::types::GpioIoBehavior as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("behavior"))?;
        Ok(Self {
            behavior: p_behavior,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.behavior;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("behavior"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.behavior;
        crate::json::key(w, &mut first, "behavior")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioBehaviorIo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["behavior"])?;
        let p_behavior = o.req(
            "behavior",
            <crate::types::GpioIoBehavior as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            behavior: p_behavior,
        })
    }
}

/// GpioBehaviorPps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioBehaviorPps {
    /// PPS input or output.
    pub behavior: crate::types::GpioPpsBehavior,
}

impl Default for GpioBehaviorPps {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioBehaviorPps {
    const ZERO: Self = Self {
        behavior: <crate::types::GpioPpsBehavior as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_behavior = <crate::types::GpioPpsBehavior as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("behavior"))?;
        Ok(Self {
            behavior: p_behavior,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.behavior;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("behavior"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.behavior;
        crate::json::key(w, &mut first, "behavior")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioBehaviorPps {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["behavior"])?;
        let p_behavior = o.req(
            "behavior",
            <crate::types::GpioPpsBehavior as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            behavior: p_behavior,
        })
    }
}

/// GpioBehaviorTimestamp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioBehaviorTimestamp {
    /// Which edges are timestamped.
    pub behavior: crate::types::GpioTimestampBehavior,
}

impl Default for GpioBehaviorTimestamp {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioBehaviorTimestamp {
    const ZERO: Self = Self {
        behavior: <crate::types::GpioTimestampBehavior as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_behavior = <crate::types::GpioTimestampBehavior as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("behavior"))?;
        Ok(Self {
            behavior: p_behavior,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.behavior;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("behavior"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.behavior;
        crate::json::key(w, &mut first, "behavior")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioBehaviorTimestamp {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["behavior"])?;
        let p_behavior = o.req(
            "behavior",
            <crate::types::GpioTimestampBehavior as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            behavior: p_behavior,
        })
    }
}

/// GpioBehaviorUart.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioBehaviorUart {
    /// UART port and direction.
    pub behavior: crate::types::GpioUartBehavior,
}

impl Default for GpioBehaviorUart {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioBehaviorUart {
    const ZERO: Self = Self {
        behavior: <crate::types::GpioUartBehavior as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_behavior = <crate::types::GpioUartBehavior as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("behavior"))?;
        Ok(Self {
            behavior: p_behavior,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.behavior;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("behavior"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.behavior;
        crate::json::key(w, &mut first, "behavior")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioBehaviorUart {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["behavior"])?;
        let p_behavior = o.req(
            "behavior",
            <crate::types::GpioUartBehavior as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            behavior: p_behavior,
        })
    }
}

/// GpioBehaviorUnused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioBehaviorUnused {
    /// Behavior value (0).
    pub behavior: crate::types::GpioUnusedBehavior,
}

impl Default for GpioBehaviorUnused {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioBehaviorUnused {
    const ZERO: Self = Self {
        behavior: <crate::types::GpioUnusedBehavior as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_behavior = <crate::types::GpioUnusedBehavior as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("behavior"))?;
        Ok(Self {
            behavior: p_behavior,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.behavior;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("behavior"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.behavior;
        crate::json::key(w, &mut first, "behavior")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioBehaviorUnused {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["behavior"])?;
        let p_behavior = o.req(
            "behavior",
            <crate::types::GpioUnusedBehavior as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            behavior: p_behavior,
        })
    }
}

/// GPIO behavior for the ENCODER feature.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpioEncoderBehavior(pub u8);

impl GpioEncoderBehavior {
    /// No behavior.
    pub const UNUSED: Self = Self(0);
    /// ENCODER_A: quadrature input A; one pin at most (the latest command wins).
    pub const ENCODER_A: Self = Self(1);
    /// ENCODER_B: quadrature input B; one pin at most (the latest command wins).
    pub const ENCODER_B: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unused"),
            1 => Some("encoder_a"),
            2 => Some("encoder_b"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unused" => Some(Self::UNUSED),
            "encoder_a" => Some(Self::ENCODER_A),
            "encoder_b" => Some(Self::ENCODER_B),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpioEncoderBehavior {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpioEncoderBehavior({} {})", self.0, name),
            None => write!(f, "GpioEncoderBehavior({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpioEncoderBehavior {
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
impl crate::json_read::FromJson for GpioEncoderBehavior {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO pin feature. What a user GPIO pin is used for; selects how the behavior byte is read.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpioFeature(pub u8);

impl GpioFeature {
    /// Pin not used; reading its state may or may not work.
    pub const UNUSED: Self = Self(0);
    /// General purpose input or output (direct control or monitoring of the pin state).
    pub const GPIO: Self = Self(1);
    /// Pulse-per-second input or output.
    pub const PPS: Self = Self(2);
    /// Motor encoder / odometer input.
    pub const ENCODER: Self = Self(3);
    /// Precision timestamping of edges (for event triggers, 0x0C,0x2E).
    pub const TIMESTAMP: Self = Self(4);
    /// UART data or control line.
    pub const UART: Self = Self(5);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unused"),
            1 => Some("gpio"),
            2 => Some("pps"),
            3 => Some("encoder"),
            4 => Some("timestamp"),
            5 => Some("uart"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unused" => Some(Self::UNUSED),
            "gpio" => Some(Self::GPIO),
            "pps" => Some(Self::PPS),
            "encoder" => Some(Self::ENCODER),
            "timestamp" => Some(Self::TIMESTAMP),
            "uart" => Some(Self::UART),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpioFeature {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpioFeature({} {})", self.0, name),
            None => write!(f, "GpioFeature({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpioFeature {
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
impl crate::json_read::FromJson for GpioFeature {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO behavior for the GPIO feature.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpioIoBehavior(pub u8);

impl GpioIoBehavior {
    /// No behavior.
    pub const UNUSED: Self = Self(0);
    /// GPIO_INPUT: the pin is an input that can be streamed or polled (the default).
    pub const INPUT: Self = Self(1);
    /// GPIO_OUTPUT_LOW: output, initially low (restored at startup if saved).
    pub const OUTPUT_LOW: Self = Self(2);
    /// GPIO_OUTPUT_HIGH: output, initially high (restored at startup if saved).
    pub const OUTPUT_HIGH: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unused"),
            1 => Some("input"),
            2 => Some("output_low"),
            3 => Some("output_high"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unused" => Some(Self::UNUSED),
            "input" => Some(Self::INPUT),
            "output_low" => Some(Self::OUTPUT_LOW),
            "output_high" => Some(Self::OUTPUT_HIGH),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpioIoBehavior {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpioIoBehavior({} {})", self.0, name),
            None => write!(f, "GpioIoBehavior({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpioIoBehavior {
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
impl crate::json_read::FromJson for GpioIoBehavior {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO pin electrical mode. Electrical configuration of a GPIO pin; which combinations a (feature, behavior) pair supports is listed in the User GPIO pin-mode table (line 1338).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GpioPinMode(pub u8);

impl GpioPinMode {
    /// Mask of `open_drain` (bit 0).
    pub const OPEN_DRAIN: u8 = 0x01;
    /// Mask of `pulldown` (bit 1).
    pub const PULLDOWN: u8 = 0x02;
    /// Mask of `pullup` (bit 2).
    pub const PULLUP: u8 = 0x04;

    /// Open-drain output: LOW or floating instead of LOW or HIGH; usually with a pull-up. (bit 0)
    pub const fn open_drain(self) -> bool {
        self.0 & Self::OPEN_DRAIN != 0
    }

    /// Sets or clears `open_drain` (bit 0).
    pub fn set_open_drain(&mut self, v: bool) {
        if v {
            self.0 |= Self::OPEN_DRAIN;
        } else {
            self.0 &= !Self::OPEN_DRAIN;
        }
    }

    /// Internal pull-down resistor enabled (not with pullup). (bit 1)
    pub const fn pulldown(self) -> bool {
        self.0 & Self::PULLDOWN != 0
    }

    /// Sets or clears `pulldown` (bit 1).
    pub fn set_pulldown(&mut self, v: bool) {
        if v {
            self.0 |= Self::PULLDOWN;
        } else {
            self.0 &= !Self::PULLDOWN;
        }
    }

    /// Internal pull-up resistor enabled (not with pulldown); may lower the allowed input voltage. (bit 2)
    pub const fn pullup(self) -> bool {
        self.0 & Self::PULLUP != 0
    }

    /// Sets or clears `pullup` (bit 2).
    pub fn set_pullup(&mut self, v: bool) {
        if v {
            self.0 |= Self::PULLUP;
        } else {
            self.0 &= !Self::PULLUP;
        }
    }
}

impl crate::wire::Wire for GpioPinMode {
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
impl crate::json_read::FromJson for GpioPinMode {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO pin states.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GpioPinStates(pub u8);

impl GpioPinStates {
    /// Mask of `pin_1` (bit 0).
    pub const PIN_1: u8 = 0x01;
    /// Mask of `pin_2` (bit 1).
    pub const PIN_2: u8 = 0x02;
    /// Mask of `pin_3` (bit 2).
    pub const PIN_3: u8 = 0x04;
    /// Mask of `pin_4` (bit 3).
    pub const PIN_4: u8 = 0x08;
    /// Mask of `reserved` (bits 4..=7).
    pub const RESERVED: u8 = 0xF0;

    /// State of GPIO pin 1. (bit 0)
    pub const fn pin_1(self) -> bool {
        self.0 & Self::PIN_1 != 0
    }

    /// Sets or clears `pin_1` (bit 0).
    pub fn set_pin_1(&mut self, v: bool) {
        if v {
            self.0 |= Self::PIN_1;
        } else {
            self.0 &= !Self::PIN_1;
        }
    }

    /// State of GPIO pin 2. (bit 1)
    pub const fn pin_2(self) -> bool {
        self.0 & Self::PIN_2 != 0
    }

    /// Sets or clears `pin_2` (bit 1).
    pub fn set_pin_2(&mut self, v: bool) {
        if v {
            self.0 |= Self::PIN_2;
        } else {
            self.0 &= !Self::PIN_2;
        }
    }

    /// State of GPIO pin 3. (bit 2)
    pub const fn pin_3(self) -> bool {
        self.0 & Self::PIN_3 != 0
    }

    /// Sets or clears `pin_3` (bit 2).
    pub fn set_pin_3(&mut self, v: bool) {
        if v {
            self.0 |= Self::PIN_3;
        } else {
            self.0 &= !Self::PIN_3;
        }
    }

    /// State of GPIO pin 4. (bit 3)
    pub const fn pin_4(self) -> bool {
        self.0 & Self::PIN_4 != 0
    }

    /// Sets or clears `pin_4` (bit 3).
    pub fn set_pin_4(&mut self, v: bool) {
        if v {
            self.0 |= Self::PIN_4;
        } else {
            self.0 &= !Self::PIN_4;
        }
    }

    /// No such pins; read as 0. Reserved. (bits 4..=7)
    pub const fn reserved(self) -> u8 {
        (self.0 & Self::RESERVED) >> 4
    }

    /// Sets `reserved` (bits 4..=7); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u8) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 4) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GpioPinStates {
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
impl crate::json_read::FromJson for GpioPinStates {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO behavior for the PPS feature.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpioPpsBehavior(pub u8);

impl GpioPpsBehavior {
    /// No behavior.
    pub const UNUSED: Self = Self(0);
    /// PPS_INPUT: receives the PPS signal; one pin at most; needs PPS source GPIO (0x0C,0x28).
    pub const INPUT: Self = Self(1);
    /// PPS_OUTPUT: transmits the device's PPS signal.
    pub const OUTPUT: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unused"),
            1 => Some("input"),
            2 => Some("output"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unused" => Some(Self::UNUSED),
            "input" => Some(Self::INPUT),
            "output" => Some(Self::OUTPUT),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpioPpsBehavior {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpioPpsBehavior({} {})", self.0, name),
            None => write!(f, "GpioPpsBehavior({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpioPpsBehavior {
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
impl crate::json_read::FromJson for GpioPpsBehavior {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO behavior for the TIMESTAMP feature.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpioTimestampBehavior(pub u8);

impl GpioTimestampBehavior {
    /// No behavior.
    pub const UNUSED: Self = Self(0);
    /// TIMESTAMP_RISING: rising edges are timestamped.
    pub const RISING: Self = Self(1);
    /// TIMESTAMP_FALLING: falling edges are timestamped.
    pub const FALLING: Self = Self(2);
    /// TIMESTAMP_EITHER: both edges are timestamped.
    pub const EITHER: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unused"),
            1 => Some("rising"),
            2 => Some("falling"),
            3 => Some("either"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unused" => Some(Self::UNUSED),
            "rising" => Some(Self::RISING),
            "falling" => Some(Self::FALLING),
            "either" => Some(Self::EITHER),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpioTimestampBehavior {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpioTimestampBehavior({} {})", self.0, name),
            None => write!(f, "GpioTimestampBehavior({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpioTimestampBehavior {
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
impl crate::json_read::FromJson for GpioTimestampBehavior {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO behavior for the UART feature.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpioUartBehavior(pub u8);

impl GpioUartBehavior {
    /// No behavior.
    pub const UNUSED: Self = Self(0);
    /// UART_PORT2_TX: UART port 2 transmit.
    pub const PORT2_TX: Self = Self(33);
    /// UART_PORT2_RX: UART port 2 receive.
    pub const PORT2_RX: Self = Self(34);
    /// UART_PORT3_TX: UART port 3 transmit.
    pub const PORT3_TX: Self = Self(49);
    /// UART_PORT3_RX: UART port 3 receive.
    pub const PORT3_RX: Self = Self(50);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unused"),
            33 => Some("port2_tx"),
            34 => Some("port2_rx"),
            49 => Some("port3_tx"),
            50 => Some("port3_rx"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unused" => Some(Self::UNUSED),
            "port2_tx" => Some(Self::PORT2_TX),
            "port2_rx" => Some(Self::PORT2_RX),
            "port3_tx" => Some(Self::PORT3_TX),
            "port3_rx" => Some(Self::PORT3_RX),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpioUartBehavior {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpioUartBehavior({} {})", self.0, name),
            None => write!(f, "GpioUartBehavior({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpioUartBehavior {
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
impl crate::json_read::FromJson for GpioUartBehavior {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO behavior for the UNUSED feature.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpioUnusedBehavior(pub u8);

impl GpioUnusedBehavior {
    /// No behavior (0 unless otherwise specified).
    pub const UNUSED: Self = Self(0);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("unused"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "unused" => Some(Self::UNUSED),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpioUnusedBehavior {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpioUnusedBehavior({} {})", self.0, name),
            None => write!(f, "GpioUnusedBehavior({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpioUnusedBehavior {
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
impl crate::json_read::FromJson for GpioUnusedBehavior {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPS time field selector.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GpsTimeField(pub u8);

impl GpsTimeField {
    /// Week number (GX5-45: GPS Week Number).
    pub const WEEK_NUMBER: Self = Self(1);
    /// Time of week in seconds (GX5-45: GPS Seconds).
    pub const TIME_OF_WEEK: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("week_number"),
            2 => Some("time_of_week"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "week_number" => Some(Self::WEEK_NUMBER),
            "time_of_week" => Some(Self::TIME_OF_WEEK),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GpsTimeField {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GpsTimeField({} {})", self.0, name),
            None => write!(f, "GpsTimeField({})", self.0),
        }
    }
}

impl crate::wire::Wire for GpsTimeField {
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
impl crate::json_read::FromJson for GpsTimeField {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GX5-45 basic device status. Remainder of the basic device status reply after the model number and selector echoes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gx5BasicStatus {
    /// Status flags (reserved).
    pub status_flags: u32,
    /// System state (values not documented).
    pub system_state: u16,
    /// Time since start-up. Units: ms.
    pub system_timer: u32,
}

impl Default for Gx5BasicStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Gx5BasicStatus {
    const ZERO: Self = Self {
        status_flags: <u32 as crate::wire::Wire>::ZERO,
        system_state: <u16 as crate::wire::Wire>::ZERO,
        system_timer: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(10);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_status_flags =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("status_flags"))?;
        let p_system_state =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("system_state"))?;
        let p_system_timer =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("system_timer"))?;
        Ok(Self {
            status_flags: p_status_flags,
            system_state: p_system_state,
            system_timer: p_system_timer,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.status_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status_flags"))?;
        let v = &self.system_state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("system_state"))?;
        let v = &self.system_timer;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("system_timer"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.status_flags;
        crate::json::key(w, &mut first, "status_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.system_state;
        crate::json::key(w, &mut first, "system_state")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.system_timer;
        crate::json::key(w, &mut first, "system_timer")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Gx5BasicStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["status_flags", "system_state", "system_timer"])?;
        let p_status_flags = o.req(
            "status_flags",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_system_state = o.req(
            "system_state",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_system_timer = o.req(
            "system_timer",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            status_flags: p_status_flags,
            system_state: p_system_state,
            system_timer: p_system_timer,
        })
    }
}

/// 3DM-GX5-45 built-in test error flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Gx5BitFlags(pub u32);

impl Gx5BitFlags {
    /// Mask of `processor_wdt_reset` (bit 0).
    pub const PROCESSOR_WDT_RESET: u32 = 0x00000001;
    /// Mask of `imu_communication_fault` (bit 8).
    pub const IMU_COMMUNICATION_FAULT: u32 = 0x00000100;
    /// Mask of `magnetometer_fault` (bit 9).
    pub const MAGNETOMETER_FAULT: u32 = 0x00000200;
    /// Mask of `pressure_sensor_fault` (bit 10).
    pub const PRESSURE_SENSOR_FAULT: u32 = 0x00000400;
    /// Mask of `filter_solution_fault` (bit 24).
    pub const FILTER_SOLUTION_FAULT: u32 = 0x01000000;

    /// Processor board: watchdog reset (latching, cleared after first commanded BIT). (bit 0)
    pub const fn processor_wdt_reset(self) -> bool {
        self.0 & Self::PROCESSOR_WDT_RESET != 0
    }

    /// Sets or clears `processor_wdt_reset` (bit 0).
    pub fn set_processor_wdt_reset(&mut self, v: bool) {
        if v {
            self.0 |= Self::PROCESSOR_WDT_RESET;
        } else {
            self.0 &= !Self::PROCESSOR_WDT_RESET;
        }
    }

    /// Sensor board: IMU communication fault. (bit 8)
    pub const fn imu_communication_fault(self) -> bool {
        self.0 & Self::IMU_COMMUNICATION_FAULT != 0
    }

    /// Sets or clears `imu_communication_fault` (bit 8).
    pub fn set_imu_communication_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::IMU_COMMUNICATION_FAULT;
        } else {
            self.0 &= !Self::IMU_COMMUNICATION_FAULT;
        }
    }

    /// Sensor board: magnetometer fault (if applicable). (bit 9)
    pub const fn magnetometer_fault(self) -> bool {
        self.0 & Self::MAGNETOMETER_FAULT != 0
    }

    /// Sets or clears `magnetometer_fault` (bit 9).
    pub fn set_magnetometer_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAGNETOMETER_FAULT;
        } else {
            self.0 &= !Self::MAGNETOMETER_FAULT;
        }
    }

    /// Sensor board: pressure sensor fault (if applicable). (bit 10)
    pub const fn pressure_sensor_fault(self) -> bool {
        self.0 & Self::PRESSURE_SENSOR_FAULT != 0
    }

    /// Sets or clears `pressure_sensor_fault` (bit 10).
    pub fn set_pressure_sensor_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::PRESSURE_SENSOR_FAULT;
        } else {
            self.0 &= !Self::PRESSURE_SENSOR_FAULT;
        }
    }

    /// Kalman filter: solution fault. (bit 24)
    pub const fn filter_solution_fault(self) -> bool {
        self.0 & Self::FILTER_SOLUTION_FAULT != 0
    }

    /// Sets or clears `filter_solution_fault` (bit 24).
    pub fn set_filter_solution_fault(&mut self, v: bool) {
        if v {
            self.0 |= Self::FILTER_SOLUTION_FAULT;
        } else {
            self.0 &= !Self::FILTER_SOLUTION_FAULT;
        }
    }
}

impl crate::wire::Wire for Gx5BitFlags {
    const ZERO: Self = Self(0);
    const FIXED_SIZE: Option<usize> = <u32 as crate::wire::Wire>::FIXED_SIZE;

    #[inline(always)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        <u32 as crate::wire::Wire>::decode(r).map(Self)
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        self.0.encode(w)
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        self.0.write_json(w)
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Gx5BitFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u32 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GNSS constellation ID (GX5-45 constellation settings).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Gx5ConstellationId(pub u8);

impl Gx5ConstellationId {
    /// GPS (G1-G32).
    pub const GPS: Self = Self(0);
    /// SBAS (S120-S158).
    pub const SBAS: Self = Self(1);
    /// Galileo (E1-E36).
    pub const GALILEO: Self = Self(2);
    /// BeiDou (B1-B37).
    pub const BEIDOU: Self = Self(3);
    /// QZSS (Q1-Q5).
    pub const QZSS: Self = Self(5);
    /// GLONASS (R1-R32).
    pub const GLONASS: Self = Self(6);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("gps"),
            1 => Some("sbas"),
            2 => Some("galileo"),
            3 => Some("beidou"),
            5 => Some("qzss"),
            6 => Some("glonass"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "gps" => Some(Self::GPS),
            "sbas" => Some(Self::SBAS),
            "galileo" => Some(Self::GALILEO),
            "beidou" => Some(Self::BEIDOU),
            "qzss" => Some(Self::QZSS),
            "glonass" => Some(Self::GLONASS),
            _ => None,
        }
    }
}

impl core::fmt::Debug for Gx5ConstellationId {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "Gx5ConstellationId({} {})", self.0, name),
            None => write!(f, "Gx5ConstellationId({})", self.0),
        }
    }
}

impl crate::wire::Wire for Gx5ConstellationId {
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
impl crate::json_read::FromJson for Gx5ConstellationId {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GX5-45 device status structure.
///
/// A union: the member is chosen by the value of an earlier selector parameter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Gx5DeviceStatus {
    /// Selected by basic (1).
    Basic(crate::types::Gx5BasicStatus),
    /// Selected by diagnostic (2).
    Diagnostic(crate::types::Gx5DiagnosticStatus),
}

impl Gx5DeviceStatus {
    /// The first member with zero values.
    pub const ZERO: Self = Self::Basic(<crate::types::Gx5BasicStatus as crate::wire::Wire>::ZERO);

    /// Selector value of this member.
    pub fn selector_value(&self) -> u8 {
        match self {
            Self::Basic(_) => 1,
            Self::Diagnostic(_) => 2,
        }
    }

    /// Reads the member selected by `selector`.
    pub fn decode_selected(
        r: &mut crate::wire::Reader<'_>,
        selector: u8,
    ) -> Result<Self, crate::error::DecodeError> {
        match selector {
            1 => <crate::types::Gx5BasicStatus as crate::wire::Wire>::decode(r).map(Self::Basic),
            2 => <crate::types::Gx5DiagnosticStatus as crate::wire::Wire>::decode(r)
                .map(Self::Diagnostic),
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
            Self::Basic(v) => crate::wire::Wire::encode(v, w),
            Self::Diagnostic(v) => crate::wire::Wire::encode(v, w),
        }
    }

    /// Writes the member's struct, or `null` for a member without data.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Basic(v) => crate::wire::Wire::write_json(v, w),
            Self::Diagnostic(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the member selected by `selector`.
    #[cfg(feature = "std")]
    pub fn from_json_selected(
        v: &crate::json_read::Json,
        selector: u8,
    ) -> Result<Self, crate::json_read::JsonError> {
        match selector {
            1 => <crate::types::Gx5BasicStatus as crate::json_read::FromJson>::from_json(v)
                .map(Self::Basic),
            2 => <crate::types::Gx5DiagnosticStatus as crate::json_read::FromJson>::from_json(v)
                .map(Self::Diagnostic),
            value => Err(crate::json_read::JsonError::new(std::format!(
                "no member for selector value {value}"
            ))),
        }
    }
}

/// GX5-45 diagnostic device status. Remainder of the diagnostic device status reply after the model number and selector echoes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gx5DiagnosticStatus {
    /// Status flags (reserved).
    pub status_flags: u32,
    /// System state (values not documented).
    pub system_state: u16,
    /// Time since start-up. Units: ms.
    pub system_timer: u32,
    /// GNSS receiver power: 1 on, 0 off.
    pub gnss_power_state: u8,
    /// Number of 1PPS pulses received. Units: count.
    pub pps_pulse_count: u32,
    /// System timer value at the last 1PPS pulse. Units: ms.
    pub last_pps_time: u32,
    /// IMU stream: 1 on, 0 off.
    pub imu_stream_enabled: u8,
    /// GNSS stream: 1 on, 0 off.
    pub gnss_stream_enabled: u8,
    /// Estimation filter stream: 1 on, 0 off.
    pub filter_stream_enabled: u8,
    /// Outgoing IMU stream packets dropped. Units: count.
    pub imu_dropped_packets: u32,
    /// Outgoing GNSS stream packets dropped. Units: count.
    pub gnss_dropped_packets: u32,
    /// Outgoing estimation filter stream packets dropped. Units: count.
    pub filter_dropped_packets: u32,
    /// Bytes written to the com port. Units: count.
    pub com_bytes_written: u32,
    /// Bytes read from the com port. Units: count.
    pub com_bytes_read: u32,
    /// Overruns when writing to the com port. Units: count.
    pub com_write_overruns: u32,
    /// IMU message parsing errors. Units: count.
    pub imu_parse_errors: u32,
    /// IMU messages read in total. Units: count.
    pub imu_messages_read: u32,
    /// System timer value at the last IMU message read. Units: ms.
    pub last_imu_message_time: u32,
    /// GNSS message parsing errors. Units: count.
    pub gnss_parse_errors: u32,
    /// GNSS messages read in total. Units: count.
    pub gnss_messages_read: u32,
    /// System timer value at the last GNSS message read. Units: ms.
    pub last_gnss_message_time: u32,
}

impl Default for Gx5DiagnosticStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Gx5DiagnosticStatus {
    const ZERO: Self = Self {
        status_flags: <u32 as crate::wire::Wire>::ZERO,
        system_state: <u16 as crate::wire::Wire>::ZERO,
        system_timer: <u32 as crate::wire::Wire>::ZERO,
        gnss_power_state: <u8 as crate::wire::Wire>::ZERO,
        pps_pulse_count: <u32 as crate::wire::Wire>::ZERO,
        last_pps_time: <u32 as crate::wire::Wire>::ZERO,
        imu_stream_enabled: <u8 as crate::wire::Wire>::ZERO,
        gnss_stream_enabled: <u8 as crate::wire::Wire>::ZERO,
        filter_stream_enabled: <u8 as crate::wire::Wire>::ZERO,
        imu_dropped_packets: <u32 as crate::wire::Wire>::ZERO,
        gnss_dropped_packets: <u32 as crate::wire::Wire>::ZERO,
        filter_dropped_packets: <u32 as crate::wire::Wire>::ZERO,
        com_bytes_written: <u32 as crate::wire::Wire>::ZERO,
        com_bytes_read: <u32 as crate::wire::Wire>::ZERO,
        com_write_overruns: <u32 as crate::wire::Wire>::ZERO,
        imu_parse_errors: <u32 as crate::wire::Wire>::ZERO,
        imu_messages_read: <u32 as crate::wire::Wire>::ZERO,
        last_imu_message_time: <u32 as crate::wire::Wire>::ZERO,
        gnss_parse_errors: <u32 as crate::wire::Wire>::ZERO,
        gnss_messages_read: <u32 as crate::wire::Wire>::ZERO,
        last_gnss_message_time: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(70);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_status_flags =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("status_flags"))?;
        let p_system_state =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("system_state"))?;
        let p_system_timer =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("system_timer"))?;
        let p_gnss_power_state =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gnss_power_state"))?;
        let p_pps_pulse_count =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pps_pulse_count"))?;
        let p_last_pps_time =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("last_pps_time"))?;
        let p_imu_stream_enabled =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("imu_stream_enabled"))?;
        let p_gnss_stream_enabled =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gnss_stream_enabled"))?;
        let p_filter_stream_enabled =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("filter_stream_enabled"))?;
        let p_imu_dropped_packets =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("imu_dropped_packets"))?;
        let p_gnss_dropped_packets =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gnss_dropped_packets"))?;
        let p_filter_dropped_packets =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("filter_dropped_packets"))?;
        let p_com_bytes_written =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("com_bytes_written"))?;
        let p_com_bytes_read =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("com_bytes_read"))?;
        let p_com_write_overruns =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("com_write_overruns"))?;
        let p_imu_parse_errors =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("imu_parse_errors"))?;
        let p_imu_messages_read =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("imu_messages_read"))?;
        let p_last_imu_message_time =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("last_imu_message_time"))?;
        let p_gnss_parse_errors =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gnss_parse_errors"))?;
        let p_gnss_messages_read =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gnss_messages_read"))?;
        let p_last_gnss_message_time =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("last_gnss_message_time"))?;
        Ok(Self {
            status_flags: p_status_flags,
            system_state: p_system_state,
            system_timer: p_system_timer,
            gnss_power_state: p_gnss_power_state,
            pps_pulse_count: p_pps_pulse_count,
            last_pps_time: p_last_pps_time,
            imu_stream_enabled: p_imu_stream_enabled,
            gnss_stream_enabled: p_gnss_stream_enabled,
            filter_stream_enabled: p_filter_stream_enabled,
            imu_dropped_packets: p_imu_dropped_packets,
            gnss_dropped_packets: p_gnss_dropped_packets,
            filter_dropped_packets: p_filter_dropped_packets,
            com_bytes_written: p_com_bytes_written,
            com_bytes_read: p_com_bytes_read,
            com_write_overruns: p_com_write_overruns,
            imu_parse_errors: p_imu_parse_errors,
            imu_messages_read: p_imu_messages_read,
            last_imu_message_time: p_last_imu_message_time,
            gnss_parse_errors: p_gnss_parse_errors,
            gnss_messages_read: p_gnss_messages_read,
            last_gnss_message_time: p_last_gnss_message_time,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.status_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status_flags"))?;
        let v = &self.system_state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("system_state"))?;
        let v = &self.system_timer;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("system_timer"))?;
        let v = &self.gnss_power_state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_power_state"))?;
        let v = &self.pps_pulse_count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pps_pulse_count"))?;
        let v = &self.last_pps_time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("last_pps_time"))?;
        let v = &self.imu_stream_enabled;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_stream_enabled"))?;
        let v = &self.gnss_stream_enabled;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_stream_enabled"))?;
        let v = &self.filter_stream_enabled;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("filter_stream_enabled"))?;
        let v = &self.imu_dropped_packets;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_dropped_packets"))?;
        let v = &self.gnss_dropped_packets;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_dropped_packets"))?;
        let v = &self.filter_dropped_packets;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("filter_dropped_packets"))?;
        let v = &self.com_bytes_written;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("com_bytes_written"))?;
        let v = &self.com_bytes_read;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("com_bytes_read"))?;
        let v = &self.com_write_overruns;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("com_write_overruns"))?;
        let v = &self.imu_parse_errors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_parse_errors"))?;
        let v = &self.imu_messages_read;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("imu_messages_read"))?;
        let v = &self.last_imu_message_time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("last_imu_message_time"))?;
        let v = &self.gnss_parse_errors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_parse_errors"))?;
        let v = &self.gnss_messages_read;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_messages_read"))?;
        let v = &self.last_gnss_message_time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("last_gnss_message_time"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.status_flags;
        crate::json::key(w, &mut first, "status_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.system_state;
        crate::json::key(w, &mut first, "system_state")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.system_timer;
        crate::json::key(w, &mut first, "system_timer")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_power_state;
        crate::json::key(w, &mut first, "gnss_power_state")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pps_pulse_count;
        crate::json::key(w, &mut first, "pps_pulse_count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.last_pps_time;
        crate::json::key(w, &mut first, "last_pps_time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_stream_enabled;
        crate::json::key(w, &mut first, "imu_stream_enabled")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_stream_enabled;
        crate::json::key(w, &mut first, "gnss_stream_enabled")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.filter_stream_enabled;
        crate::json::key(w, &mut first, "filter_stream_enabled")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_dropped_packets;
        crate::json::key(w, &mut first, "imu_dropped_packets")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_dropped_packets;
        crate::json::key(w, &mut first, "gnss_dropped_packets")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.filter_dropped_packets;
        crate::json::key(w, &mut first, "filter_dropped_packets")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.com_bytes_written;
        crate::json::key(w, &mut first, "com_bytes_written")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.com_bytes_read;
        crate::json::key(w, &mut first, "com_bytes_read")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.com_write_overruns;
        crate::json::key(w, &mut first, "com_write_overruns")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_parse_errors;
        crate::json::key(w, &mut first, "imu_parse_errors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.imu_messages_read;
        crate::json::key(w, &mut first, "imu_messages_read")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.last_imu_message_time;
        crate::json::key(w, &mut first, "last_imu_message_time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_parse_errors;
        crate::json::key(w, &mut first, "gnss_parse_errors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_messages_read;
        crate::json::key(w, &mut first, "gnss_messages_read")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.last_gnss_message_time;
        crate::json::key(w, &mut first, "last_gnss_message_time")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Gx5DiagnosticStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "status_flags",
                "system_state",
                "system_timer",
                "gnss_power_state",
                "pps_pulse_count",
                "last_pps_time",
                "imu_stream_enabled",
                "gnss_stream_enabled",
                "filter_stream_enabled",
                "imu_dropped_packets",
                "gnss_dropped_packets",
                "filter_dropped_packets",
                "com_bytes_written",
                "com_bytes_read",
                "com_write_overruns",
                "imu_parse_errors",
                "imu_messages_read",
                "last_imu_message_time",
                "gnss_parse_errors",
                "gnss_messages_read",
                "last_gnss_message_time",
            ],
        )?;
        let p_status_flags = o.req(
            "status_flags",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_system_state = o.req(
            "system_state",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_system_timer = o.req(
            "system_timer",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_power_state = o.req(
            "gnss_power_state",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_pps_pulse_count = o.req(
            "pps_pulse_count",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_last_pps_time = o.req(
            "last_pps_time",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_stream_enabled = o.req(
            "imu_stream_enabled",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_stream_enabled = o.req(
            "gnss_stream_enabled",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_filter_stream_enabled = o.req(
            "filter_stream_enabled",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_dropped_packets = o.req(
            "imu_dropped_packets",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_dropped_packets = o.req(
            "gnss_dropped_packets",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_filter_dropped_packets = o.req(
            "filter_dropped_packets",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_com_bytes_written = o.req(
            "com_bytes_written",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_com_bytes_read = o.req(
            "com_bytes_read",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_com_write_overruns = o.req(
            "com_write_overruns",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_parse_errors = o.req(
            "imu_parse_errors",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_imu_messages_read = o.req(
            "imu_messages_read",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_last_imu_message_time = o.req(
            "last_imu_message_time",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_parse_errors = o.req(
            "gnss_parse_errors",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_messages_read = o.req(
            "gnss_messages_read",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_last_gnss_message_time = o.req(
            "last_gnss_message_time",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            status_flags: p_status_flags,
            system_state: p_system_state,
            system_timer: p_system_timer,
            gnss_power_state: p_gnss_power_state,
            pps_pulse_count: p_pps_pulse_count,
            last_pps_time: p_last_pps_time,
            imu_stream_enabled: p_imu_stream_enabled,
            gnss_stream_enabled: p_gnss_stream_enabled,
            filter_stream_enabled: p_filter_stream_enabled,
            imu_dropped_packets: p_imu_dropped_packets,
            gnss_dropped_packets: p_gnss_dropped_packets,
            filter_dropped_packets: p_filter_dropped_packets,
            com_bytes_written: p_com_bytes_written,
            com_bytes_read: p_com_bytes_read,
            com_write_overruns: p_com_write_overruns,
            imu_parse_errors: p_imu_parse_errors,
            imu_messages_read: p_imu_messages_read,
            last_imu_message_time: p_last_imu_message_time,
            gnss_parse_errors: p_gnss_parse_errors,
            gnss_messages_read: p_gnss_messages_read,
            last_gnss_message_time: p_last_gnss_message_time,
        })
    }
}

/// Poll format entry (GX5-45).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gx5PollDescriptor {
    /// Data field descriptor to include in the polled packet.
    pub descriptor: u8,
    /// Reserved; 0 in every example.
    pub reserved: u16,
}

impl Default for Gx5PollDescriptor {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Gx5PollDescriptor {
    const ZERO: Self = Self {
        descriptor: <u8 as crate::wire::Wire>::ZERO,
        reserved: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(3);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_descriptor = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("descriptor"))?;
        let p_reserved = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?;
        Ok(Self {
            descriptor: p_descriptor,
            reserved: p_reserved,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.descriptor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("descriptor"))?;
        let v = &self.reserved;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.descriptor;
        crate::json::key(w, &mut first, "descriptor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved;
        crate::json::key(w, &mut first, "reserved")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Gx5PollDescriptor {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["descriptor", "reserved"])?;
        let p_descriptor = o.req("descriptor", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_reserved = o.req("reserved", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            descriptor: p_descriptor,
            reserved: p_reserved,
        })
    }
}

/// Poll option selector. First byte of the GX5-45 poll commands; chooses whether the ACK/NACK is sent.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Gx5PollOption(pub u8);

impl Gx5PollOption {
    /// Normal ACK/NACK reply.
    pub const NORMAL: Self = Self(0);
    /// No ACK/NACK reply; only the data packet is sent.
    pub const SUPPRESS_ACK: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("normal"),
            1 => Some("suppress_ack"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "normal" => Some(Self::NORMAL),
            "suppress_ack" => Some(Self::SUPPRESS_ACK),
            _ => None,
        }
    }
}

impl core::fmt::Debug for Gx5PollOption {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "Gx5PollOption({} {})", self.0, name),
            None => write!(f, "Gx5PollOption({})", self.0),
        }
    }
}

impl crate::wire::Wire for Gx5PollOption {
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
impl crate::json_read::FromJson for Gx5PollOption {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Continuous data stream selector (GX5-45). Which data stream the GX5-45 Enable/Disable Continuous Data Stream command controls.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Gx5StreamSelector(pub u8);

impl Gx5StreamSelector {
    /// IMU data stream (set 0x80).
    pub const IMU: Self = Self(1);
    /// Estimation filter data stream (set 0x82).
    pub const ESTIMATION_FILTER: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("imu"),
            3 => Some("estimation_filter"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "imu" => Some(Self::IMU),
            "estimation_filter" => Some(Self::ESTIMATION_FILTER),
            _ => None,
        }
    }
}

impl core::fmt::Debug for Gx5StreamSelector {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "Gx5StreamSelector({} {})", self.0, name),
            None => write!(f, "Gx5StreamSelector({})", self.0),
        }
    }
}

impl crate::wire::Wire for Gx5StreamSelector {
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
impl crate::json_read::FromJson for Gx5StreamSelector {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Allowed automatic heading alignment methods.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct HeadingAlignmentMethods(pub u8);

impl HeadingAlignmentMethods {
    /// Mask of `dual_antenna` (bit 0).
    pub const DUAL_ANTENNA: u8 = 0x01;
    /// Mask of `kinematic` (bit 1).
    pub const KINEMATIC: u8 = 0x02;
    /// Mask of `magnetometer` (bit 2).
    pub const MAGNETOMETER: u8 = 0x04;
    /// Mask of `external` (bit 3).
    pub const EXTERNAL: u8 = 0x08;

    /// Dual-antenna GNSS alignment. (bit 0)
    pub const fn dual_antenna(self) -> bool {
        self.0 & Self::DUAL_ANTENNA != 0
    }

    /// Sets or clears `dual_antenna` (bit 0).
    pub fn set_dual_antenna(&mut self, v: bool) {
        if v {
            self.0 |= Self::DUAL_ANTENNA;
        } else {
            self.0 &= !Self::DUAL_ANTENNA;
        }
    }

    /// GNSS kinematic alignment: the GNSS velocity (above 2 m/s) determines the initial heading. (bit 1)
    pub const fn kinematic(self) -> bool {
        self.0 & Self::KINEMATIC != 0
    }

    /// Sets or clears `kinematic` (bit 1).
    pub fn set_kinematic(&mut self, v: bool) {
        if v {
            self.0 |= Self::KINEMATIC;
        } else {
            self.0 &= !Self::KINEMATIC;
        }
    }

    /// The internal magnetometer determines the initial heading. (bit 2)
    pub const fn magnetometer(self) -> bool {
        self.0 & Self::MAGNETOMETER != 0
    }

    /// Sets or clears `magnetometer` (bit 2).
    pub fn set_magnetometer(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAGNETOMETER;
        } else {
            self.0 &= !Self::MAGNETOMETER;
        }
    }

    /// An external heading input determines the initial heading. (bit 3)
    pub const fn external(self) -> bool {
        self.0 & Self::EXTERNAL != 0
    }

    /// Sets or clears `external` (bit 3).
    pub fn set_external(&mut self, v: bool) {
        if v {
            self.0 |= Self::EXTERNAL;
        } else {
            self.0 &= !Self::EXTERNAL;
        }
    }
}

impl crate::wire::Wire for HeadingAlignmentMethods {
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
impl crate::json_read::FromJson for HeadingAlignmentMethods {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Heading update source. Which aiding sources the filter uses for heading updates.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct HeadingUpdateSource(pub u8);

impl HeadingUpdateSource {
    /// No heading aiding; heading still converges from GNSS under sufficient acceleration.
    pub const NONE: Self = Self(0);
    /// Internal magnetometer.
    pub const MAGNETOMETER: Self = Self(1);
    /// Internal GNSS velocity vector (needs little side-slip and the vehicle X axis along the direction of travel).
    pub const GNSS_VELOCITY: Self = Self(2);
    /// External heading messages (0x0D,0x17 / 0x0D,0x1F).
    pub const EXTERNAL: Self = Self(3);
    /// GNSS velocity vector and magnetometer.
    pub const GNSS_VELOCITY_AND_MAGNETOMETER: Self = Self(4);
    /// GNSS velocity vector and external heading messages.
    pub const GNSS_VELOCITY_AND_EXTERNAL: Self = Self(5);
    /// Magnetometer and external heading messages.
    pub const MAGNETOMETER_AND_EXTERNAL: Self = Self(6);
    /// GNSS velocity vector, magnetometer and external heading messages.
    pub const GNSS_VELOCITY_MAGNETOMETER_AND_EXTERNAL: Self = Self(7);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("magnetometer"),
            2 => Some("gnss_velocity"),
            3 => Some("external"),
            4 => Some("gnss_velocity_and_magnetometer"),
            5 => Some("gnss_velocity_and_external"),
            6 => Some("magnetometer_and_external"),
            7 => Some("gnss_velocity_magnetometer_and_external"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "magnetometer" => Some(Self::MAGNETOMETER),
            "gnss_velocity" => Some(Self::GNSS_VELOCITY),
            "external" => Some(Self::EXTERNAL),
            "gnss_velocity_and_magnetometer" => Some(Self::GNSS_VELOCITY_AND_MAGNETOMETER),
            "gnss_velocity_and_external" => Some(Self::GNSS_VELOCITY_AND_EXTERNAL),
            "magnetometer_and_external" => Some(Self::MAGNETOMETER_AND_EXTERNAL),
            "gnss_velocity_magnetometer_and_external" => {
                Some(Self::GNSS_VELOCITY_MAGNETOMETER_AND_EXTERNAL)
            }
            _ => None,
        }
    }
}

impl core::fmt::Debug for HeadingUpdateSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "HeadingUpdateSource({} {})", self.0, name),
            None => write!(f, "HeadingUpdateSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for HeadingUpdateSource {
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
impl crate::json_read::FromJson for HeadingUpdateSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Source of a magnetic field parameter (declination, inclination, magnitude). Where the filter takes a local magnetic field parameter from: nowhere (a fixed fallback), the internal World Magnetic Model, or a value the user supplies.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct MagneticParamSource(pub u8);

impl MagneticParamSource {
    /// No source: no correction (declination, inclination) or a fixed 0.5 gauss (magnitude).
    pub const NONE: Self = Self(1);
    /// Internal World Magnetic Model at the current position estimate (default).
    pub const WMM: Self = Self(2);
    /// Value supplied by the user; the device does not validate it.
    pub const MANUAL: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("none"),
            2 => Some("wmm"),
            3 => Some("manual"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "wmm" => Some(Self::WMM),
            "manual" => Some(Self::MANUAL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for MagneticParamSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "MagneticParamSource({} {})", self.0, name),
            None => write!(f, "MagneticParamSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for MagneticParamSource {
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
impl crate::json_read::FromJson for MagneticParamSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// MessageParams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MessageParams {
    /// MIP data descriptor set.
    pub desc_set: u8,
    /// Decimation from the base rate; 0 emits one packet per activation.
    pub decimation: u16,
    /// Number of fields in the packet (at most 12).
    pub num_fields: u8,
    /// Field descriptors.
    pub descriptors: crate::bounded::BoundedVec<u8, 12>,
}

impl Default for MessageParams {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MessageParams {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        decimation: <u16 as crate::wire::Wire>::ZERO,
        num_fields: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<u8, 12> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_decimation = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("decimation"))?;
        let p_num_fields = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_fields"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<u8, 12>::decode_counted(r, u64::from(p_num_fields))
                .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            desc_set: p_desc_set,
            decimation: p_decimation,
            num_fields: p_num_fields,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.decimation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("decimation"))?;
        let v = &self.num_fields;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_fields"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_fields))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.decimation;
        crate::json::key(w, &mut first, "decimation")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_fields;
        crate::json::key(w, &mut first, "num_fields")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MessageParams {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["desc_set", "decimation", "num_fields", "descriptors"],
        )?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_decimation = o.req("decimation", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_num_fields = o.req("num_fields", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_descriptors = o.req(
            "descriptors",
            <crate::bounded::BoundedVec<u8, 12> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            desc_set: p_desc_set,
            decimation: p_decimation,
            num_fields: p_num_fields,
            descriptors: p_descriptors,
        })
    }
}

/// NMEA message format entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NmeaMessage {
    /// NMEA sentence type (GGA, GLL, GSV, RMC, VTG, HDT, ZDA, GST, PMSRA, PMSRR; codes not documented).
    pub message_id: u8,
    /// Talker ID (GN, GP, GA, GL; ignored for GSV and proprietary sentences; codes not documented).
    pub talker_id: u8,
    /// Data descriptor set the sentence is built from (IMU, filter, GNSS 1 or 2).
    pub source_desc_set: u8,
    /// Decimation relative to the base rate of the source descriptor set.
    pub decimation: u16,
}

impl Default for NmeaMessage {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NmeaMessage {
    const ZERO: Self = Self {
        message_id: <u8 as crate::wire::Wire>::ZERO,
        talker_id: <u8 as crate::wire::Wire>::ZERO,
        source_desc_set: <u8 as crate::wire::Wire>::ZERO,
        decimation: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_message_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("message_id"))?;
        let p_talker_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("talker_id"))?;
        let p_source_desc_set =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("source_desc_set"))?;
        let p_decimation = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("decimation"))?;
        Ok(Self {
            message_id: p_message_id,
            talker_id: p_talker_id,
            source_desc_set: p_source_desc_set,
            decimation: p_decimation,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.message_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("message_id"))?;
        let v = &self.talker_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("talker_id"))?;
        let v = &self.source_desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source_desc_set"))?;
        let v = &self.decimation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("decimation"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.message_id;
        crate::json::key(w, &mut first, "message_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.talker_id;
        crate::json::key(w, &mut first, "talker_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.source_desc_set;
        crate::json::key(w, &mut first, "source_desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.decimation;
        crate::json::key(w, &mut first, "decimation")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for NmeaMessage {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["message_id", "talker_id", "source_desc_set", "decimation"],
        )?;
        let p_message_id = o.req("message_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_talker_id = o.req("talker_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_source_desc_set = o.req(
            "source_desc_set",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_decimation = o.req("decimation", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            message_id: p_message_id,
            talker_id: p_talker_id,
            source_desc_set: p_source_desc_set,
            decimation: p_decimation,
        })
    }
}

/// Odometer data valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct OdometerDataValidFlags(pub u16);

impl OdometerDataValidFlags {
    /// Mask of `valid` (bit 0).
    pub const VALID: u16 = 0x0001;
    /// Mask of `reserved` (bits 1..=15).
    pub const RESERVED: u16 = 0xFFFE;

    /// Set when the odometer is configured (speed and uncertainty are valid). (bit 0)
    pub const fn valid(self) -> bool {
        self.0 & Self::VALID != 0
    }

    /// Sets or clears `valid` (bit 0).
    pub fn set_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::VALID;
        } else {
            self.0 &= !Self::VALID;
        }
    }

    /// Not described. Reserved. (bits 1..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 1
    }

    /// Sets `reserved` (bits 1..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 1) & Self::RESERVED);
    }
}

impl crate::wire::Wire for OdometerDataValidFlags {
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
impl crate::json_read::FromJson for OdometerDataValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Odometer mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct OdometerMode(pub u8);

impl OdometerMode {
    /// Encoder disabled.
    pub const DISABLED: Self = Self(0);
    /// Quadrature encoder mode.
    pub const QUADRATURE: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("disabled"),
            2 => Some("quadrature"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "disabled" => Some(Self::DISABLED),
            "quadrature" => Some(Self::QUADRATURE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for OdometerMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "OdometerMode({} {})", self.0, name),
            None => write!(f, "OdometerMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for OdometerMode {
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
impl crate::json_read::FromJson for OdometerMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Sensor over-range status. One bit per sensor axis that is near or beyond its range.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct OverrangeStatusFlags(pub u16);

impl OverrangeStatusFlags {
    /// Mask of `accel_x` (bit 0).
    pub const ACCEL_X: u16 = 0x0001;
    /// Mask of `accel_y` (bit 1).
    pub const ACCEL_Y: u16 = 0x0002;
    /// Mask of `accel_z` (bit 2).
    pub const ACCEL_Z: u16 = 0x0004;
    /// Mask of `reserved_3` (bit 3).
    pub const RESERVED_3: u16 = 0x0008;
    /// Mask of `gyro_x` (bit 4).
    pub const GYRO_X: u16 = 0x0010;
    /// Mask of `gyro_y` (bit 5).
    pub const GYRO_Y: u16 = 0x0020;
    /// Mask of `gyro_z` (bit 6).
    pub const GYRO_Z: u16 = 0x0040;
    /// Mask of `reserved_7` (bit 7).
    pub const RESERVED_7: u16 = 0x0080;
    /// Mask of `mag_x` (bit 8).
    pub const MAG_X: u16 = 0x0100;
    /// Mask of `mag_y` (bit 9).
    pub const MAG_Y: u16 = 0x0200;
    /// Mask of `mag_z` (bit 10).
    pub const MAG_Z: u16 = 0x0400;
    /// Mask of `reserved_11` (bit 11).
    pub const RESERVED_11: u16 = 0x0800;
    /// Mask of `press` (bit 12).
    pub const PRESS: u16 = 0x1000;
    /// Mask of `reserved_13_15` (bits 13..=15).
    pub const RESERVED_13_15: u16 = 0xE000;

    /// Accelerometer X axis over range. (bit 0)
    pub const fn accel_x(self) -> bool {
        self.0 & Self::ACCEL_X != 0
    }

    /// Sets or clears `accel_x` (bit 0).
    pub fn set_accel_x(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCEL_X;
        } else {
            self.0 &= !Self::ACCEL_X;
        }
    }

    /// Accelerometer Y axis over range. (bit 1)
    pub const fn accel_y(self) -> bool {
        self.0 & Self::ACCEL_Y != 0
    }

    /// Sets or clears `accel_y` (bit 1).
    pub fn set_accel_y(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCEL_Y;
        } else {
            self.0 &= !Self::ACCEL_Y;
        }
    }

    /// Accelerometer Z axis over range. (bit 2)
    pub const fn accel_z(self) -> bool {
        self.0 & Self::ACCEL_Z != 0
    }

    /// Sets or clears `accel_z` (bit 2).
    pub fn set_accel_z(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACCEL_Z;
        } else {
            self.0 &= !Self::ACCEL_Z;
        }
    }

    /// Not listed. Reserved. (bit 3)
    pub const fn reserved_3(self) -> bool {
        self.0 & Self::RESERVED_3 != 0
    }

    /// Sets or clears `reserved_3` (bit 3).
    pub fn set_reserved_3(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_3;
        } else {
            self.0 &= !Self::RESERVED_3;
        }
    }

    /// Gyroscope X axis over range. (bit 4)
    pub const fn gyro_x(self) -> bool {
        self.0 & Self::GYRO_X != 0
    }

    /// Sets or clears `gyro_x` (bit 4).
    pub fn set_gyro_x(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYRO_X;
        } else {
            self.0 &= !Self::GYRO_X;
        }
    }

    /// Gyroscope Y axis over range. (bit 5)
    pub const fn gyro_y(self) -> bool {
        self.0 & Self::GYRO_Y != 0
    }

    /// Sets or clears `gyro_y` (bit 5).
    pub fn set_gyro_y(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYRO_Y;
        } else {
            self.0 &= !Self::GYRO_Y;
        }
    }

    /// Gyroscope Z axis over range. (bit 6)
    pub const fn gyro_z(self) -> bool {
        self.0 & Self::GYRO_Z != 0
    }

    /// Sets or clears `gyro_z` (bit 6).
    pub fn set_gyro_z(&mut self, v: bool) {
        if v {
            self.0 |= Self::GYRO_Z;
        } else {
            self.0 &= !Self::GYRO_Z;
        }
    }

    /// Not listed. Reserved. (bit 7)
    pub const fn reserved_7(self) -> bool {
        self.0 & Self::RESERVED_7 != 0
    }

    /// Sets or clears `reserved_7` (bit 7).
    pub fn set_reserved_7(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_7;
        } else {
            self.0 &= !Self::RESERVED_7;
        }
    }

    /// Magnetometer X axis over range. (bit 8)
    pub const fn mag_x(self) -> bool {
        self.0 & Self::MAG_X != 0
    }

    /// Sets or clears `mag_x` (bit 8).
    pub fn set_mag_x(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAG_X;
        } else {
            self.0 &= !Self::MAG_X;
        }
    }

    /// Magnetometer Y axis over range. (bit 9)
    pub const fn mag_y(self) -> bool {
        self.0 & Self::MAG_Y != 0
    }

    /// Sets or clears `mag_y` (bit 9).
    pub fn set_mag_y(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAG_Y;
        } else {
            self.0 &= !Self::MAG_Y;
        }
    }

    /// Magnetometer Z axis over range. (bit 10)
    pub const fn mag_z(self) -> bool {
        self.0 & Self::MAG_Z != 0
    }

    /// Sets or clears `mag_z` (bit 10).
    pub fn set_mag_z(&mut self, v: bool) {
        if v {
            self.0 |= Self::MAG_Z;
        } else {
            self.0 &= !Self::MAG_Z;
        }
    }

    /// Not listed. Reserved. (bit 11)
    pub const fn reserved_11(self) -> bool {
        self.0 & Self::RESERVED_11 != 0
    }

    /// Sets or clears `reserved_11` (bit 11).
    pub fn set_reserved_11(&mut self, v: bool) {
        if v {
            self.0 |= Self::RESERVED_11;
        } else {
            self.0 &= !Self::RESERVED_11;
        }
    }

    /// Pressure sensor over range. (bit 12)
    pub const fn press(self) -> bool {
        self.0 & Self::PRESS != 0
    }

    /// Sets or clears `press` (bit 12).
    pub fn set_press(&mut self, v: bool) {
        if v {
            self.0 |= Self::PRESS;
        } else {
            self.0 &= !Self::PRESS;
        }
    }

    /// Not listed. Reserved. (bits 13..=15)
    pub const fn reserved_13_15(self) -> u16 {
        (self.0 & Self::RESERVED_13_15) >> 13
    }

    /// Sets `reserved_13_15` (bits 13..=15); higher bits of `v` are ignored.
    pub fn set_reserved_13_15(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED_13_15) | ((v << 13) & Self::RESERVED_13_15);
    }
}

impl crate::wire::Wire for OverrangeStatusFlags {
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
impl crate::json_read::FromJson for OverrangeStatusFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Pitch/roll aiding source.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PitchRollAidingSource(pub u8);

impl PitchRollAidingSource {
    /// No pitch/roll aiding (disabled).
    pub const NONE: Self = Self(0);
    /// Gravity vector aiding enabled.
    pub const GRAVITY_VECTOR: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("gravity_vector"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "gravity_vector" => Some(Self::GRAVITY_VECTOR),
            _ => None,
        }
    }
}

impl core::fmt::Debug for PitchRollAidingSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "PitchRollAidingSource({} {})", self.0, name),
            None => write!(f, "PitchRollAidingSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for PitchRollAidingSource {
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
impl crate::json_read::FromJson for PitchRollAidingSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// PPS source.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PpsSource(pub u8);

impl PpsSource {
    /// No PPS (the table says it is not valid as a command value; see note).
    pub const DISABLED: Self = Self(0);
    /// PPS from GNSS receiver 1.
    pub const RECEIVER_1: Self = Self(1);
    /// PPS from GNSS receiver 2.
    pub const RECEIVER_2: Self = Self(2);
    /// PPS applied to a GPIO pin (pin chosen with GPIO Configuration 0x0C,0x41).
    pub const GPIO: Self = Self(3);
    /// PPS generated from the system oscillator.
    pub const GENERATED: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("disabled"),
            1 => Some("receiver_1"),
            2 => Some("receiver_2"),
            3 => Some("gpio"),
            4 => Some("generated"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "disabled" => Some(Self::DISABLED),
            "receiver_1" => Some(Self::RECEIVER_1),
            "receiver_2" => Some(Self::RECEIVER_2),
            "gpio" => Some(Self::GPIO),
            "generated" => Some(Self::GENERATED),
            _ => None,
        }
    }
}

impl core::fmt::Debug for PpsSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "PpsSource({} {})", self.0, name),
            None => write!(f, "PpsSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for PpsSource {
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
impl crate::json_read::FromJson for PpsSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter reference point.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ReferencePointSelector(pub u8);

impl ReferencePointSelector {
    /// The origin of the vehicle (the only value; the parameter is reserved and must be 1).
    pub const VEH: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("veh"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "veh" => Some(Self::VEH),
            _ => None,
        }
    }
}

impl core::fmt::Debug for ReferencePointSelector {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "ReferencePointSelector({} {})", self.0, name),
            None => write!(f, "ReferencePointSelector({})", self.0),
        }
    }
}

impl crate::wire::Wire for ReferencePointSelector {
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
impl crate::json_read::FromJson for ReferencePointSelector {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Reference location source for relative position outputs.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct RelativePositionSource(pub u8);

impl RelativePositionSource {
    /// Automatic: the RTK base station location.
    pub const AUTO: Self = Self(0);
    /// The reference coordinates given in the command.
    pub const MANUAL: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("auto"),
            1 => Some("manual"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "auto" => Some(Self::AUTO),
            "manual" => Some(Self::MANUAL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for RelativePositionSource {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "RelativePositionSource({} {})", self.0, name),
            None => write!(f, "RelativePositionSource({})", self.0),
        }
    }
}

impl crate::wire::Wire for RelativePositionSource {
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
impl crate::json_read::FromJson for RelativePositionSource {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// RTK corrections epoch status. Status of the corrections received during the epoch.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct RtkCorrectionsEpochStatus(pub u16);

impl RtkCorrectionsEpochStatus {
    /// Mask of `antenna_location_received` (bit 0).
    pub const ANTENNA_LOCATION_RECEIVED: u16 = 0x0001;
    /// Mask of `antenna_description_received` (bit 1).
    pub const ANTENNA_DESCRIPTION_RECEIVED: u16 = 0x0002;
    /// Mask of `gps_received` (bit 2).
    pub const GPS_RECEIVED: u16 = 0x0004;
    /// Mask of `glonass_received` (bit 3).
    pub const GLONASS_RECEIVED: u16 = 0x0008;
    /// Mask of `galileo_received` (bit 4).
    pub const GALILEO_RECEIVED: u16 = 0x0010;
    /// Mask of `beidou_received` (bit 5).
    pub const BEIDOU_RECEIVED: u16 = 0x0020;
    /// Mask of `using_gps_msm_messages` (bit 6).
    pub const USING_GPS_MSM_MESSAGES: u16 = 0x0040;
    /// Mask of `using_glonass_msm_messages` (bit 7).
    pub const USING_GLONASS_MSM_MESSAGES: u16 = 0x0080;
    /// Mask of `dongle_status_read_failed` (bit 8).
    pub const DONGLE_STATUS_READ_FAILED: u16 = 0x0100;
    /// Mask of `reserved` (bits 9..=15).
    pub const RESERVED: u16 = 0xFE00;

    /// Antenna location (station coordinates) received. (bit 0)
    pub const fn antenna_location_received(self) -> bool {
        self.0 & Self::ANTENNA_LOCATION_RECEIVED != 0
    }

    /// Sets or clears `antenna_location_received` (bit 0).
    pub fn set_antenna_location_received(&mut self, v: bool) {
        if v {
            self.0 |= Self::ANTENNA_LOCATION_RECEIVED;
        } else {
            self.0 &= !Self::ANTENNA_LOCATION_RECEIVED;
        }
    }

    /// Antenna description received. (bit 1)
    pub const fn antenna_description_received(self) -> bool {
        self.0 & Self::ANTENNA_DESCRIPTION_RECEIVED != 0
    }

    /// Sets or clears `antenna_description_received` (bit 1).
    pub fn set_antenna_description_received(&mut self, v: bool) {
        if v {
            self.0 |= Self::ANTENNA_DESCRIPTION_RECEIVED;
        } else {
            self.0 &= !Self::ANTENNA_DESCRIPTION_RECEIVED;
        }
    }

    /// GPS corrections received. (bit 2)
    pub const fn gps_received(self) -> bool {
        self.0 & Self::GPS_RECEIVED != 0
    }

    /// Sets or clears `gps_received` (bit 2).
    pub fn set_gps_received(&mut self, v: bool) {
        if v {
            self.0 |= Self::GPS_RECEIVED;
        } else {
            self.0 &= !Self::GPS_RECEIVED;
        }
    }

    /// GLONASS corrections received. (bit 3)
    pub const fn glonass_received(self) -> bool {
        self.0 & Self::GLONASS_RECEIVED != 0
    }

    /// Sets or clears `glonass_received` (bit 3).
    pub fn set_glonass_received(&mut self, v: bool) {
        if v {
            self.0 |= Self::GLONASS_RECEIVED;
        } else {
            self.0 &= !Self::GLONASS_RECEIVED;
        }
    }

    /// Galileo corrections received. (bit 4)
    pub const fn galileo_received(self) -> bool {
        self.0 & Self::GALILEO_RECEIVED != 0
    }

    /// Sets or clears `galileo_received` (bit 4).
    pub fn set_galileo_received(&mut self, v: bool) {
        if v {
            self.0 |= Self::GALILEO_RECEIVED;
        } else {
            self.0 &= !Self::GALILEO_RECEIVED;
        }
    }

    /// BeiDou corrections received. (bit 5)
    pub const fn beidou_received(self) -> bool {
        self.0 & Self::BEIDOU_RECEIVED != 0
    }

    /// Sets or clears `beidou_received` (bit 5).
    pub fn set_beidou_received(&mut self, v: bool) {
        if v {
            self.0 |= Self::BEIDOU_RECEIVED;
        } else {
            self.0 &= !Self::BEIDOU_RECEIVED;
        }
    }

    /// GPS corrections come from MSM messages rather than RTCM 1001-1004. (bit 6)
    pub const fn using_gps_msm_messages(self) -> bool {
        self.0 & Self::USING_GPS_MSM_MESSAGES != 0
    }

    /// Sets or clears `using_gps_msm_messages` (bit 6).
    pub fn set_using_gps_msm_messages(&mut self, v: bool) {
        if v {
            self.0 |= Self::USING_GPS_MSM_MESSAGES;
        } else {
            self.0 &= !Self::USING_GPS_MSM_MESSAGES;
        }
    }

    /// GLONASS corrections come from MSM messages rather than RTCM 1009-1012. (bit 7)
    pub const fn using_glonass_msm_messages(self) -> bool {
        self.0 & Self::USING_GLONASS_MSM_MESSAGES != 0
    }

    /// Sets or clears `using_glonass_msm_messages` (bit 7).
    pub fn set_using_glonass_msm_messages(&mut self, v: bool) {
        if v {
            self.0 |= Self::USING_GLONASS_MSM_MESSAGES;
        } else {
            self.0 &= !Self::USING_GLONASS_MSM_MESSAGES;
        }
    }

    /// Reading the dongle status was attempted and failed. (bit 8)
    pub const fn dongle_status_read_failed(self) -> bool {
        self.0 & Self::DONGLE_STATUS_READ_FAILED != 0
    }

    /// Sets or clears `dongle_status_read_failed` (bit 8).
    pub fn set_dongle_status_read_failed(&mut self, v: bool) {
        if v {
            self.0 |= Self::DONGLE_STATUS_READ_FAILED;
        } else {
            self.0 &= !Self::DONGLE_STATUS_READ_FAILED;
        }
    }

    /// Not named by the manual. Reserved. (bits 9..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 9
    }

    /// Sets `reserved` (bits 9..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 9) & Self::RESERVED);
    }
}

impl crate::wire::Wire for RtkCorrectionsEpochStatus {
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
impl crate::json_read::FromJson for RtkCorrectionsEpochStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// RTK corrections status valid flags. Which parameters of the RTK corrections status field are valid.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct RtkCorrectionsStatusValidFlags(pub u16);

impl RtkCorrectionsStatusValidFlags {
    /// Mask of `tow` (bit 0).
    pub const TOW: u16 = 0x0001;
    /// Mask of `week_number` (bit 1).
    pub const WEEK_NUMBER: u16 = 0x0002;
    /// Mask of `epoch_status` (bit 2).
    pub const EPOCH_STATUS: u16 = 0x0004;
    /// Mask of `dongle_status` (bit 3).
    pub const DONGLE_STATUS: u16 = 0x0008;
    /// Mask of `gps_latency` (bit 4).
    pub const GPS_LATENCY: u16 = 0x0010;
    /// Mask of `glonass_latency` (bit 5).
    pub const GLONASS_LATENCY: u16 = 0x0020;
    /// Mask of `galileo_latency` (bit 6).
    pub const GALILEO_LATENCY: u16 = 0x0040;
    /// Mask of `beidou_latency` (bit 7).
    pub const BEIDOU_LATENCY: u16 = 0x0080;
    /// Mask of `flags` (bits 0..=7).
    pub const FLAGS: u16 = 0x00FF;
    /// Mask of `reserved` (bits 8..=15).
    pub const RESERVED: u16 = 0xFF00;

    /// Time of week valid. (bit 0)
    pub const fn tow(self) -> bool {
        self.0 & Self::TOW != 0
    }

    /// Sets or clears `tow` (bit 0).
    pub fn set_tow(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW;
        } else {
            self.0 &= !Self::TOW;
        }
    }

    /// Week number valid. (bit 1)
    pub const fn week_number(self) -> bool {
        self.0 & Self::WEEK_NUMBER != 0
    }

    /// Sets or clears `week_number` (bit 1).
    pub fn set_week_number(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER;
        } else {
            self.0 &= !Self::WEEK_NUMBER;
        }
    }

    /// Epoch status valid. (bit 2)
    pub const fn epoch_status(self) -> bool {
        self.0 & Self::EPOCH_STATUS != 0
    }

    /// Sets or clears `epoch_status` (bit 2).
    pub fn set_epoch_status(&mut self, v: bool) {
        if v {
            self.0 |= Self::EPOCH_STATUS;
        } else {
            self.0 &= !Self::EPOCH_STATUS;
        }
    }

    /// Dongle status valid. (bit 3)
    pub const fn dongle_status(self) -> bool {
        self.0 & Self::DONGLE_STATUS != 0
    }

    /// Sets or clears `dongle_status` (bit 3).
    pub fn set_dongle_status(&mut self, v: bool) {
        if v {
            self.0 |= Self::DONGLE_STATUS;
        } else {
            self.0 &= !Self::DONGLE_STATUS;
        }
    }

    /// GPS correction latency valid. (bit 4)
    pub const fn gps_latency(self) -> bool {
        self.0 & Self::GPS_LATENCY != 0
    }

    /// Sets or clears `gps_latency` (bit 4).
    pub fn set_gps_latency(&mut self, v: bool) {
        if v {
            self.0 |= Self::GPS_LATENCY;
        } else {
            self.0 &= !Self::GPS_LATENCY;
        }
    }

    /// GLONASS correction latency valid. (bit 5)
    pub const fn glonass_latency(self) -> bool {
        self.0 & Self::GLONASS_LATENCY != 0
    }

    /// Sets or clears `glonass_latency` (bit 5).
    pub fn set_glonass_latency(&mut self, v: bool) {
        if v {
            self.0 |= Self::GLONASS_LATENCY;
        } else {
            self.0 &= !Self::GLONASS_LATENCY;
        }
    }

    /// Galileo correction latency valid. (bit 6)
    pub const fn galileo_latency(self) -> bool {
        self.0 & Self::GALILEO_LATENCY != 0
    }

    /// Sets or clears `galileo_latency` (bit 6).
    pub fn set_galileo_latency(&mut self, v: bool) {
        if v {
            self.0 |= Self::GALILEO_LATENCY;
        } else {
            self.0 &= !Self::GALILEO_LATENCY;
        }
    }

    /// BeiDou correction latency valid. (bit 7)
    pub const fn beidou_latency(self) -> bool {
        self.0 & Self::BEIDOU_LATENCY != 0
    }

    /// Sets or clears `beidou_latency` (bit 7).
    pub fn set_beidou_latency(&mut self, v: bool) {
        if v {
            self.0 |= Self::BEIDOU_LATENCY;
        } else {
            self.0 &= !Self::BEIDOU_LATENCY;
        }
    }

    /// All flags. (bits 0..=7)
    pub const fn flags(self) -> u16 {
        self.0 & Self::FLAGS
    }

    /// Sets `flags` (bits 0..=7); higher bits of `v` are ignored.
    pub fn set_flags(&mut self, v: u16) {
        self.0 = (self.0 & !Self::FLAGS) | (v & Self::FLAGS);
    }

    /// Not named by the manual. Reserved. (bits 8..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 8
    }

    /// Sets `reserved` (bits 8..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 8) & Self::RESERVED);
    }
}

impl crate::wire::Wire for RtkCorrectionsStatusValidFlags {
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
impl crate::json_read::FromJson for RtkCorrectionsStatusValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// SBAS options.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SbasOptions(pub u16);

impl SbasOptions {
    /// Mask of `enable_ranging` (bit 0).
    pub const ENABLE_RANGING: u16 = 0x0001;
    /// Mask of `enable_corrections` (bit 1).
    pub const ENABLE_CORRECTIONS: u16 = 0x0002;
    /// Mask of `apply_integrity` (bit 2).
    pub const APPLY_INTEGRITY: u16 = 0x0004;

    /// Use SBAS pseudoranges in the position solution (GX5-45 default on). (bit 0)
    pub const fn enable_ranging(self) -> bool {
        self.0 & Self::ENABLE_RANGING != 0
    }

    /// Sets or clears `enable_ranging` (bit 0).
    pub fn set_enable_ranging(&mut self, v: bool) {
        if v {
            self.0 |= Self::ENABLE_RANGING;
        } else {
            self.0 &= !Self::ENABLE_RANGING;
        }
    }

    /// Use SBAS differential corrections (GX5-45 default on). (bit 1)
    pub const fn enable_corrections(self) -> bool {
        self.0 & Self::ENABLE_CORRECTIONS != 0
    }

    /// Sets or clears `enable_corrections` (bit 1).
    pub fn set_enable_corrections(&mut self, v: bool) {
        if v {
            self.0 |= Self::ENABLE_CORRECTIONS;
        } else {
            self.0 &= !Self::ENABLE_CORRECTIONS;
        }
    }

    /// Use SBAS integrity information; only satellites with integrity data are used. (bit 2)
    pub const fn apply_integrity(self) -> bool {
        self.0 & Self::APPLY_INTEGRITY != 0
    }

    /// Sets or clears `apply_integrity` (bit 2).
    pub fn set_apply_integrity(&mut self, v: bool) {
        if v {
            self.0 |= Self::APPLY_INTEGRITY;
        } else {
            self.0 &= !Self::APPLY_INTEGRITY;
        }
    }
}

impl crate::wire::Wire for SbasOptions {
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
impl crate::json_read::FromJson for SbasOptions {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Sensor GPS timestamp flags (0x80,0x12). Status of the GPS timestamp attached to sensor data. Bits 0-2 mean the same on both devices (the GX5-45 calls them PPS Beacon Good, GPS Time Refresh and GPS Time Initialized); bits 3 and 4 exist only on the CV7.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SensorGpsTimestampFlags(pub u16);

impl SensorGpsTimestampFlags {
    /// Mask of `pps_valid` (bit 0).
    pub const PPS_VALID: u16 = 0x0001;
    /// Mask of `time_refresh` (bit 1).
    pub const TIME_REFRESH: u16 = 0x0002;
    /// Mask of `time_initialized` (bit 2).
    pub const TIME_INITIALIZED: u16 = 0x0004;
    /// Mask of `tow_valid` (bit 3).
    pub const TOW_VALID: u16 = 0x0008;
    /// Mask of `week_number_valid` (bit 4).
    pub const WEEK_NUMBER_VALID: u16 = 0x0010;
    /// Mask of `reserved` (bits 5..=15).
    pub const RESERVED: u16 = 0xFFE0;

    /// PPS signal present (GX5-45: PPS Beacon Good); when clear the internal clock stands in for the PPS. (bit 0)
    pub const fn pps_valid(self) -> bool {
        self.0 & Self::PPS_VALID != 0
    }

    /// Sets or clears `pps_valid` (bit 0).
    pub fn set_pps_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::PPS_VALID;
        } else {
            self.0 &= !Self::PPS_VALID;
        }
    }

    /// Toggles each time the time is updated (GPS time, or the GPS Time Update command 0x01,0x72). (bit 1)
    pub const fn time_refresh(self) -> bool {
        self.0 & Self::TIME_REFRESH != 0
    }

    /// Sets or clears `time_refresh` (bit 1).
    pub fn set_time_refresh(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIME_REFRESH;
        } else {
            self.0 &= !Self::TIME_REFRESH;
        }
    }

    /// Set once the time has been set at least once (the first time refresh); stays set. (bit 2)
    pub const fn time_initialized(self) -> bool {
        self.0 & Self::TIME_INITIALIZED != 0
    }

    /// Sets or clears `time_initialized` (bit 2).
    pub fn set_time_initialized(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIME_INITIALIZED;
        } else {
            self.0 &= !Self::TIME_INITIALIZED;
        }
    }

    /// Time of week is valid. (bit 3)
    pub const fn tow_valid(self) -> bool {
        self.0 & Self::TOW_VALID != 0
    }

    /// Sets or clears `tow_valid` (bit 3).
    pub fn set_tow_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW_VALID;
        } else {
            self.0 &= !Self::TOW_VALID;
        }
    }

    /// Week number is valid. (bit 4)
    pub const fn week_number_valid(self) -> bool {
        self.0 & Self::WEEK_NUMBER_VALID != 0
    }

    /// Sets or clears `week_number_valid` (bit 4).
    pub fn set_week_number_valid(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER_VALID;
        } else {
            self.0 &= !Self::WEEK_NUMBER_VALID;
        }
    }

    /// Not defined by either manual (GX5-45: bits 3-15). Reserved. (bits 5..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 5
    }

    /// Sets `reserved` (bits 5..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 5) & Self::RESERVED);
    }
}

impl crate::wire::Wire for SensorGpsTimestampFlags {
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
impl crate::json_read::FromJson for SensorGpsTimestampFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Calibrated sensor range entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorRangeEntry {
    /// Value to use as setting in Sensor Range (0x0C,0x52).
    pub setting: u8,
    /// Range this setting gives; units depend on the sensor (see SensorRangeType).
    pub range: f32,
}

impl Default for SensorRangeEntry {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorRangeEntry {
    const ZERO: Self = Self {
        setting: <u8 as crate::wire::Wire>::ZERO,
        range: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_setting = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("setting"))?;
        let p_range = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("range"))?;
        Ok(Self {
            setting: p_setting,
            range: p_range,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.setting;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("setting"))?;
        let v = &self.range;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("range"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.setting;
        crate::json::key(w, &mut first, "setting")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.range;
        crate::json::key(w, &mut first, "range")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorRangeEntry {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["setting", "range"])?;
        let p_setting = o.req("setting", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_range = o.req("range", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            setting: p_setting,
            range: p_range,
        })
    }
}

/// Sensor whose range is set or queried.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SensorRangeType(pub u8);

impl SensorRangeType {
    /// All sensors; only with save, load and default.
    pub const ALL: Self = Self(0);
    /// Accelerometer; range in g.
    pub const ACCEL: Self = Self(1);
    /// Gyroscope; range in degrees/s.
    pub const GYRO: Self = Self(2);
    /// Magnetometer; range in Gauss.
    pub const MAG: Self = Self(3);
    /// Pressure sensor; range in hPa.
    pub const PRESS: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("all"),
            1 => Some("accel"),
            2 => Some("gyro"),
            3 => Some("mag"),
            4 => Some("press"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "all" => Some(Self::ALL),
            "accel" => Some(Self::ACCEL),
            "gyro" => Some(Self::GYRO),
            "mag" => Some(Self::MAG),
            "press" => Some(Self::PRESS),
            _ => None,
        }
    }
}

impl core::fmt::Debug for SensorRangeType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "SensorRangeType({} {})", self.0, name),
            None => write!(f, "SensorRangeType({})", self.0),
        }
    }
}

impl crate::wire::Wire for SensorRangeType {
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
impl crate::json_read::FromJson for SensorRangeType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Shared GPS timestamp valid flags.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SharedGpsTimestampValidFlags(pub u16);

impl SharedGpsTimestampValidFlags {
    /// Mask of `tow` (bit 0).
    pub const TOW: u16 = 0x0001;
    /// Mask of `week_number` (bit 1).
    pub const WEEK_NUMBER: u16 = 0x0002;
    /// Mask of `time_valid` (bits 0..=1).
    pub const TIME_VALID: u16 = 0x0003;
    /// Mask of `reserved` (bits 2..=15).
    pub const RESERVED: u16 = 0xFFFC;

    /// The whole-second time of week has been set. (bit 0)
    pub const fn tow(self) -> bool {
        self.0 & Self::TOW != 0
    }

    /// Sets or clears `tow` (bit 0).
    pub fn set_tow(&mut self, v: bool) {
        if v {
            self.0 |= Self::TOW;
        } else {
            self.0 &= !Self::TOW;
        }
    }

    /// The week number has been set. (bit 1)
    pub const fn week_number(self) -> bool {
        self.0 & Self::WEEK_NUMBER != 0
    }

    /// Sets or clears `week_number` (bit 1).
    pub fn set_week_number(&mut self, v: bool) {
        if v {
            self.0 |= Self::WEEK_NUMBER;
        } else {
            self.0 &= !Self::WEEK_NUMBER;
        }
    }

    /// Both time of week and week number have been set. (bits 0..=1)
    pub const fn time_valid(self) -> u16 {
        self.0 & Self::TIME_VALID
    }

    /// Sets `time_valid` (bits 0..=1); higher bits of `v` are ignored.
    pub fn set_time_valid(&mut self, v: u16) {
        self.0 = (self.0 & !Self::TIME_VALID) | (v & Self::TIME_VALID);
    }

    /// Not listed. Reserved. (bits 2..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 2
    }

    /// Sets `reserved` (bits 2..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 2) & Self::RESERVED);
    }
}

impl crate::wire::Wire for SharedGpsTimestampValidFlags {
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
impl crate::json_read::FromJson for SharedGpsTimestampValidFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// SPARTN connection type.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SpartnConnectionType(pub u8);

impl SpartnConnectionType {
    /// No SPARTN connection.
    pub const NONE: Self = Self(0);
    /// Corrections over a network connection (e.g. NTRIP).
    pub const NETWORK: Self = Self(1);
    /// Corrections from an L-band correction receiver.
    pub const L_BAND: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("network"),
            2 => Some("l_band"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "network" => Some(Self::NETWORK),
            "l_band" => Some(Self::L_BAND),
            _ => None,
        }
    }
}

impl core::fmt::Debug for SpartnConnectionType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "SpartnConnectionType({} {})", self.0, name),
            None => write!(f, "SpartnConnectionType({})", self.0),
        }
    }
}

impl crate::wire::Wire for SpartnConnectionType {
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
impl crate::json_read::FromJson for SpartnConnectionType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Supported action type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SupportedActionType {
    /// Action type, as in Event Action Configuration (0x0C,0x2F).
    pub r#type: crate::types::ActionType,
    /// Maximum number of instances of this type.
    pub count: u8,
}

impl Default for SupportedActionType {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SupportedActionType {
    const ZERO: Self = Self {
        r#type: <crate::types::ActionType as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_type =
            <crate::types::ActionType as crate::wire::Wire>::decode(r).map_err(|e| e.at("type"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        Ok(Self {
            r#type: p_type,
            count: p_count,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SupportedActionType {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["type", "count"])?;
        let p_type = o.req(
            "type",
            <crate::types::ActionType as crate::json_read::FromJson>::from_json,
        )?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            r#type: p_type,
            count: p_count,
        })
    }
}

/// Supported actions (query = action types).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SupportedActions {
    /// Number of action slots; instance numbers run 1..max_instances.
    pub max_instances: u8,
    /// Number of supported action types.
    pub num_entries: u8,
    /// Supported action types.
    pub entries: crate::bounded::BoundedVec<crate::types::SupportedActionType, 125>,
}

impl Default for SupportedActions {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SupportedActions {
    const ZERO: Self = Self {
        max_instances: <u8 as crate::wire::Wire>::ZERO,
        num_entries: <u8 as crate::wire::Wire>::ZERO,
        entries: <crate::bounded::BoundedVec<crate::types::SupportedActionType, 125> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_max_instances =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_instances"))?;
        let p_num_entries =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_entries"))?;
        let p_entries =
            crate::bounded::BoundedVec::<crate::types::SupportedActionType, 125>::decode_counted(
                r,
                u64::from(p_num_entries),
            )
            .map_err(|e| e.at("entries"))?;
        Ok(Self {
            max_instances: p_max_instances,
            num_entries: p_num_entries,
            entries: p_entries,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.max_instances;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_instances"))?;
        let v = &self.num_entries;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_entries"))?;
        let v = &self.entries;
        v.encode_counted(w, u64::from(self.num_entries))
            .map_err(|e| e.at("entries"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.max_instances;
        crate::json::key(w, &mut first, "max_instances")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_entries;
        crate::json::key(w, &mut first, "num_entries")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.entries;
        crate::json::key(w, &mut first, "entries")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SupportedActions {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["max_instances", "num_entries", "entries"])?;
        let p_max_instances = o.req(
            "max_instances",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_entries = o.req("num_entries", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_entries = o.req("entries", <crate::bounded::BoundedVec<crate::types::SupportedActionType, 125> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            max_instances: p_max_instances,
            num_entries: p_num_entries,
            entries: p_entries,
        })
    }
}

/// Supported event types, by query.
///
/// A union: the member is chosen by the value of an earlier selector parameter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SupportedEventsInfo {
    /// Selected by trigger_types (1).
    TriggerTypes(crate::types::SupportedTriggers),
    /// Selected by action_types (2).
    ActionTypes(crate::types::SupportedActions),
}

impl SupportedEventsInfo {
    /// The first member with zero values.
    pub const ZERO: Self =
        Self::TriggerTypes(<crate::types::SupportedTriggers as crate::wire::Wire>::ZERO);

    /// Selector value of this member.
    pub fn selector_value(&self) -> u8 {
        match self {
            Self::TriggerTypes(_) => 1,
            Self::ActionTypes(_) => 2,
        }
    }

    /// Reads the member selected by `selector`.
    pub fn decode_selected(
        r: &mut crate::wire::Reader<'_>,
        selector: u8,
    ) -> Result<Self, crate::error::DecodeError> {
        match selector {
            1 => <crate::types::SupportedTriggers as crate::wire::Wire>::decode(r)
                .map(Self::TriggerTypes),
            2 => <crate::types::SupportedActions as crate::wire::Wire>::decode(r)
                .map(Self::ActionTypes),
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
            Self::TriggerTypes(v) => crate::wire::Wire::encode(v, w),
            Self::ActionTypes(v) => crate::wire::Wire::encode(v, w),
        }
    }

    /// Writes the member's struct, or `null` for a member without data.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::TriggerTypes(v) => crate::wire::Wire::write_json(v, w),
            Self::ActionTypes(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the member selected by `selector`.
    #[cfg(feature = "std")]
    pub fn from_json_selected(
        v: &crate::json_read::Json,
        selector: u8,
    ) -> Result<Self, crate::json_read::JsonError> {
        match selector {
            1 => <crate::types::SupportedTriggers as crate::json_read::FromJson>::from_json(v)
                .map(Self::TriggerTypes),
            2 => <crate::types::SupportedActions as crate::json_read::FromJson>::from_json(v)
                .map(Self::ActionTypes),
            value => Err(crate::json_read::JsonError::new(std::format!(
                "no member for selector value {value}"
            ))),
        }
    }
}

/// Supported events query.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SupportedEventsQuery(pub u8);

impl SupportedEventsQuery {
    /// Report the supported trigger types and how many of each.
    pub const TRIGGER_TYPES: Self = Self(1);
    /// Report the supported action types and how many of each.
    pub const ACTION_TYPES: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("trigger_types"),
            2 => Some("action_types"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "trigger_types" => Some(Self::TRIGGER_TYPES),
            "action_types" => Some(Self::ACTION_TYPES),
            _ => None,
        }
    }
}

impl core::fmt::Debug for SupportedEventsQuery {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "SupportedEventsQuery({} {})", self.0, name),
            None => write!(f, "SupportedEventsQuery({})", self.0),
        }
    }
}

impl crate::wire::Wire for SupportedEventsQuery {
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
impl crate::json_read::FromJson for SupportedEventsQuery {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Supported trigger type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SupportedTriggerType {
    /// Trigger type, as in Event Trigger Configuration (0x0C,0x2E).
    pub r#type: crate::types::TriggerType,
    /// Maximum number of instances of this type.
    pub count: u8,
}

impl Default for SupportedTriggerType {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SupportedTriggerType {
    const ZERO: Self = Self {
        r#type: <crate::types::TriggerType as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_type = <crate::types::TriggerType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        Ok(Self {
            r#type: p_type,
            count: p_count,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SupportedTriggerType {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["type", "count"])?;
        let p_type = o.req(
            "type",
            <crate::types::TriggerType as crate::json_read::FromJson>::from_json,
        )?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            r#type: p_type,
            count: p_count,
        })
    }
}

/// Supported triggers (query = trigger types).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SupportedTriggers {
    /// Number of trigger slots; instance numbers run 1..max_instances.
    pub max_instances: u8,
    /// Number of supported trigger types.
    pub num_entries: u8,
    /// Supported trigger types.
    pub entries: crate::bounded::BoundedVec<crate::types::SupportedTriggerType, 125>,
}

impl Default for SupportedTriggers {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SupportedTriggers {
    const ZERO: Self = Self {
        max_instances: <u8 as crate::wire::Wire>::ZERO,
        num_entries: <u8 as crate::wire::Wire>::ZERO,
        entries: <crate::bounded::BoundedVec<crate::types::SupportedTriggerType, 125> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_max_instances =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_instances"))?;
        let p_num_entries =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_entries"))?;
        let p_entries =
            crate::bounded::BoundedVec::<crate::types::SupportedTriggerType, 125>::decode_counted(
                r,
                u64::from(p_num_entries),
            )
            .map_err(|e| e.at("entries"))?;
        Ok(Self {
            max_instances: p_max_instances,
            num_entries: p_num_entries,
            entries: p_entries,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.max_instances;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_instances"))?;
        let v = &self.num_entries;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_entries"))?;
        let v = &self.entries;
        v.encode_counted(w, u64::from(self.num_entries))
            .map_err(|e| e.at("entries"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.max_instances;
        crate::json::key(w, &mut first, "max_instances")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_entries;
        crate::json::key(w, &mut first, "num_entries")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.entries;
        crate::json::key(w, &mut first, "entries")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SupportedTriggers {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["max_instances", "num_entries", "entries"])?;
        let p_max_instances = o.req(
            "max_instances",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_entries = o.req("num_entries", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_entries = o.req("entries", <crate::bounded::BoundedVec<crate::types::SupportedTriggerType, 125> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            max_instances: p_max_instances,
            num_entries: p_num_entries,
            entries: p_entries,
        })
    }
}

/// Communication mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SystemCommMode(pub u8);

impl SystemCommMode {
    /// 3DM-GX5-45 MIP packets (default).
    pub const STANDARD: Self = Self(1);
    /// Direct to the internal IMU: MIP IMU protocol.
    pub const SENSOR_DIRECT: Self = Self(2);
    /// Direct to the GNSS receiver: NMEA and UBX (GNSS models only).
    pub const GNSS_DIRECT: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("standard"),
            2 => Some("sensor_direct"),
            3 => Some("gnss_direct"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "standard" => Some(Self::STANDARD),
            "sensor_direct" => Some(Self::SENSOR_DIRECT),
            "gnss_direct" => Some(Self::GNSS_DIRECT),
            _ => None,
        }
    }
}

impl core::fmt::Debug for SystemCommMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "SystemCommMode({} {})", self.0, name),
            None => write!(f, "SystemCommMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for SystemCommMode {
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
impl crate::json_read::FromJson for SystemCommMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Tare orientation axes. Axes to tare; 0 (no bit set) resets all axes.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct TareAxes(pub u8);

impl TareAxes {
    /// Mask of `roll` (bit 0).
    pub const ROLL: u8 = 0x01;
    /// Mask of `pitch` (bit 1).
    pub const PITCH: u8 = 0x02;
    /// Mask of `yaw` (bit 2).
    pub const YAW: u8 = 0x04;

    /// Tare the roll axis. (bit 0)
    pub const fn roll(self) -> bool {
        self.0 & Self::ROLL != 0
    }

    /// Sets or clears `roll` (bit 0).
    pub fn set_roll(&mut self, v: bool) {
        if v {
            self.0 |= Self::ROLL;
        } else {
            self.0 &= !Self::ROLL;
        }
    }

    /// Tare the pitch axis. (bit 1)
    pub const fn pitch(self) -> bool {
        self.0 & Self::PITCH != 0
    }

    /// Sets or clears `pitch` (bit 1).
    pub fn set_pitch(&mut self, v: bool) {
        if v {
            self.0 |= Self::PITCH;
        } else {
            self.0 &= !Self::PITCH;
        }
    }

    /// Tare the yaw axis. (bit 2)
    pub const fn yaw(self) -> bool {
        self.0 & Self::YAW != 0
    }

    /// Sets or clears `yaw` (bit 2).
    pub fn set_yaw(&mut self, v: bool) {
        if v {
            self.0 |= Self::YAW;
        } else {
            self.0 &= !Self::YAW;
        }
    }
}

impl crate::wire::Wire for TareAxes {
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
impl crate::json_read::FromJson for TareAxes {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// ThresholdParams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThresholdParams {
    /// Descriptor set of the target data quantity.
    pub desc_set: u8,
    /// Field descriptor of the target data quantity.
    pub field_desc: u8,
    /// 1-based index of the target parameter within the field.
    pub param_id: u8,
    /// Type of comparison.
    pub r#type: crate::types::ThresholdType,
    /// Low threshold (window) or active time (interval).
    pub low_thres: f64,
    /// High threshold (window) or interval (interval).
    pub high_thres: f64,
}

impl Default for ThresholdParams {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ThresholdParams {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        field_desc: <u8 as crate::wire::Wire>::ZERO,
        param_id: <u8 as crate::wire::Wire>::ZERO,
        r#type: <crate::types::ThresholdType as crate::wire::Wire>::ZERO,
        low_thres: <f64 as crate::wire::Wire>::ZERO,
        high_thres: <f64 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(20);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_field_desc = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("field_desc"))?;
        let p_param_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("param_id"))?;
        let p_type = <crate::types::ThresholdType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        let p_low_thres = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_thres"))?;
        let p_high_thres = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_thres"))?;
        Ok(Self {
            desc_set: p_desc_set,
            field_desc: p_field_desc,
            param_id: p_param_id,
            r#type: p_type,
            low_thres: p_low_thres,
            high_thres: p_high_thres,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.field_desc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("field_desc"))?;
        let v = &self.param_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("param_id"))?;
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.low_thres;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_thres"))?;
        let v = &self.high_thres;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_thres"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.field_desc;
        crate::json::key(w, &mut first, "field_desc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.param_id;
        crate::json::key(w, &mut first, "param_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.low_thres;
        crate::json::key(w, &mut first, "low_thres")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high_thres;
        crate::json::key(w, &mut first, "high_thres")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ThresholdParams {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "desc_set",
                "field_desc",
                "param_id",
                "type",
                "low_thres",
                "high_thres",
            ],
        )?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_field_desc = o.req("field_desc", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_param_id = o.req("param_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.req(
            "type",
            <crate::types::ThresholdType as crate::json_read::FromJson>::from_json,
        )?;
        let p_low_thres = o.req("low_thres", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_high_thres = o.req("high_thres", <f64 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            desc_set: p_desc_set,
            field_desc: p_field_desc,
            param_id: p_param_id,
            r#type: p_type,
            low_thres: p_low_thres,
            high_thres: p_high_thres,
        })
    }
}

/// Threshold comparison type.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ThresholdType(pub u8);

impl ThresholdType {
    /// Active if low_thres <= value <= high_thres (reversed thresholds invert it).
    pub const WINDOW: Self = Self(1);
    /// Active when (value % high_thres) <= low_thres: periodic triggering.
    pub const INTERVAL: Self = Self(2);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("window"),
            2 => Some("interval"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "window" => Some(Self::WINDOW),
            "interval" => Some(Self::INTERVAL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for ThresholdType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "ThresholdType({} {})", self.0, name),
            None => write!(f, "ThresholdType({})", self.0),
        }
    }
}

impl crate::wire::Wire for ThresholdType {
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
impl crate::json_read::FromJson for ThresholdType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPIO trigger mode.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TriggerGpioMode(pub u8);

impl TriggerGpioMode {
    /// The pin has no effect and the trigger never activates.
    pub const DISABLED: Self = Self(0);
    /// Active while the pin is high.
    pub const WHILE_HIGH: Self = Self(1);
    /// Active while the pin is low.
    pub const WHILE_LOW: Self = Self(2);
    /// Use if the pin is configured for timestamping (0x0C,0x41).
    pub const EDGE: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("disabled"),
            1 => Some("while_high"),
            2 => Some("while_low"),
            4 => Some("edge"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "disabled" => Some(Self::DISABLED),
            "while_high" => Some(Self::WHILE_HIGH),
            "while_low" => Some(Self::WHILE_LOW),
            "edge" => Some(Self::EDGE),
            _ => None,
        }
    }
}

impl core::fmt::Debug for TriggerGpioMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "TriggerGpioMode({} {})", self.0, name),
            None => write!(f, "TriggerGpioMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for TriggerGpioMode {
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
impl crate::json_read::FromJson for TriggerGpioMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// TriggerGpioParams.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriggerGpioParams {
    /// GPIO pin number.
    pub pin: u8,
    /// How the pin state affects the trigger.
    pub mode: crate::types::TriggerGpioMode,
}

impl Default for TriggerGpioParams {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for TriggerGpioParams {
    const ZERO: Self = Self {
        pin: <u8 as crate::wire::Wire>::ZERO,
        mode: <crate::types::TriggerGpioMode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pin = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pin"))?;
        let p_mode = <crate::types::TriggerGpioMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        Ok(Self {
            pin: p_pin,
            mode: p_mode,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pin;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin"))?;
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pin;
        crate::json::key(w, &mut first, "pin")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for TriggerGpioParams {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["pin", "mode"])?;
        let p_pin = o.req("pin", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_mode = o.req(
            "mode",
            <crate::types::TriggerGpioMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            pin: p_pin,
            mode: p_mode,
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
    Gpio(crate::types::TriggerGpioParams),
    /// Selected by threshold (2).
    Threshold(crate::types::ThresholdParams),
    /// Selected by combination (3).
    Combination(crate::types::CombinationParams),
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
            Self::Combination(_) => 3,
        }
    }

    /// Reads the member selected by `selector`.
    pub fn decode_selected(
        r: &mut crate::wire::Reader<'_>,
        selector: u8,
    ) -> Result<Self, crate::error::DecodeError> {
        match selector {
            0 => Ok(Self::None),
            1 => <crate::types::TriggerGpioParams as crate::wire::Wire>::decode(r).map(Self::Gpio),
            2 => {
                <crate::types::ThresholdParams as crate::wire::Wire>::decode(r).map(Self::Threshold)
            }
            3 => <crate::types::CombinationParams as crate::wire::Wire>::decode(r)
                .map(Self::Combination),
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
            Self::Combination(v) => crate::wire::Wire::encode(v, w),
        }
    }

    /// Writes the member's struct, or `null` for a member without data.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::None => w.write_str("null"),
            Self::Gpio(v) => crate::wire::Wire::write_json(v, w),
            Self::Threshold(v) => crate::wire::Wire::write_json(v, w),
            Self::Combination(v) => crate::wire::Wire::write_json(v, w),
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
            1 => <crate::types::TriggerGpioParams as crate::json_read::FromJson>::from_json(v)
                .map(Self::Gpio),
            2 => <crate::types::ThresholdParams as crate::json_read::FromJson>::from_json(v)
                .map(Self::Threshold),
            3 => <crate::types::CombinationParams as crate::json_read::FromJson>::from_json(v)
                .map(Self::Combination),
            value => Err(crate::json_read::JsonError::new(std::format!(
                "no member for selector value {value}"
            ))),
        }
    }
}

/// Event trigger status.
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct TriggerStatus(pub u8);

impl TriggerStatus {
    /// Mask of `active` (bit 0).
    pub const ACTIVE: u8 = 0x01;
    /// Mask of `enabled` (bit 1).
    pub const ENABLED: u8 = 0x02;
    /// Mask of `test` (bit 2).
    pub const TEST: u8 = 0x04;

    /// The trigger is currently active (by its logic or in test mode). (bit 0)
    pub const fn active(self) -> bool {
        self.0 & Self::ACTIVE != 0
    }

    /// Sets or clears `active` (bit 0).
    pub fn set_active(&mut self, v: bool) {
        if v {
            self.0 |= Self::ACTIVE;
        } else {
            self.0 &= !Self::ACTIVE;
        }
    }

    /// The trigger is enabled. (bit 1)
    pub const fn enabled(self) -> bool {
        self.0 & Self::ENABLED != 0
    }

    /// Sets or clears `enabled` (bit 1).
    pub fn set_enabled(&mut self, v: bool) {
        if v {
            self.0 |= Self::ENABLED;
        } else {
            self.0 &= !Self::ENABLED;
        }
    }

    /// The trigger is in test mode. (bit 2)
    pub const fn test(self) -> bool {
        self.0 & Self::TEST != 0
    }

    /// Sets or clears `test` (bit 2).
    pub fn set_test(&mut self, v: bool) {
        if v {
            self.0 |= Self::TEST;
        } else {
            self.0 &= !Self::TEST;
        }
    }
}

impl crate::wire::Wire for TriggerStatus {
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
impl crate::json_read::FromJson for TriggerStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// TriggerStatusEntry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriggerStatusEntry {
    /// Configured trigger type.
    pub r#type: crate::types::TriggerType,
    /// Trigger status.
    pub status: crate::types::TriggerStatus,
}

impl Default for TriggerStatusEntry {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for TriggerStatusEntry {
    const ZERO: Self = Self {
        r#type: <crate::types::TriggerType as crate::wire::Wire>::ZERO,
        status: <crate::types::TriggerStatus as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_type = <crate::types::TriggerType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        let p_status = <crate::types::TriggerStatus as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("status"))?;
        Ok(Self {
            r#type: p_type,
            status: p_status,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.status;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status;
        crate::json::key(w, &mut first, "status")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for TriggerStatusEntry {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["type", "status"])?;
        let p_type = o.req(
            "type",
            <crate::types::TriggerType as crate::json_read::FromJson>::from_json,
        )?;
        let p_status = o.req(
            "status",
            <crate::types::TriggerStatus as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            r#type: p_type,
            status: p_status,
        })
    }
}

/// Event trigger type.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TriggerType(pub u8);

impl TriggerType {
    /// No trigger selected. The state will always be inactive.
    pub const NONE: Self = Self(0);
    /// Trigger based on the state of a GPIO pin.
    pub const GPIO: Self = Self(1);
    /// Compare a data quantity against a high and low threshold.
    pub const THRESHOLD: Self = Self(2);
    /// Logical combination of two or more triggers.
    pub const COMBINATION: Self = Self(3);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("none"),
            1 => Some("gpio"),
            2 => Some("threshold"),
            3 => Some("combination"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Self::NONE),
            "gpio" => Some(Self::GPIO),
            "threshold" => Some(Self::THRESHOLD),
            "combination" => Some(Self::COMBINATION),
            _ => None,
        }
    }
}

impl core::fmt::Debug for TriggerType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "TriggerType({} {})", self.0, name),
            None => write!(f, "TriggerType({})", self.0),
        }
    }
}

impl crate::wire::Wire for TriggerType {
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
impl crate::json_read::FromJson for TriggerType {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Vehicle dynamics mode. Dynamics model the filter assumes for the vehicle (altitude and velocity limits).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct VehicleDynamicsMode(pub u8);

impl VehicleDynamicsMode {
    /// Low-acceleration applications (default); up to 12,000 m, 310 m/s horizontal, 50 m/s vertical.
    pub const PORTABLE: Self = Self(1);
    /// Wheeled vehicles with low vertical acceleration; up to 6,000 m, 84 m/s horizontal, 15 m/s vertical.
    pub const AUTOMOTIVE: Self = Self(2);
    /// Airborne up to 2 g; up to 50,000 m, 250 m/s horizontal, 100 m/s vertical.
    pub const AIRBORNE: Self = Self(3);
    /// Airborne up to 4 g; same altitude and velocity limits as airborne.
    pub const AIRBORNE_HIGH_G: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("portable"),
            2 => Some("automotive"),
            3 => Some("airborne"),
            4 => Some("airborne_high_g"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "portable" => Some(Self::PORTABLE),
            "automotive" => Some(Self::AUTOMOTIVE),
            "airborne" => Some(Self::AIRBORNE),
            "airborne_high_g" => Some(Self::AIRBORNE_HIGH_G),
            _ => None,
        }
    }
}

impl core::fmt::Debug for VehicleDynamicsMode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "VehicleDynamicsMode({} {})", self.0, name),
            None => write!(f, "VehicleDynamicsMode({})", self.0),
        }
    }
}

impl crate::wire::Wire for VehicleDynamicsMode {
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
impl crate::json_read::FromJson for VehicleDynamicsMode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}
