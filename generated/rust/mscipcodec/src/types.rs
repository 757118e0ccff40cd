//! Named types of the Memsense MS-CIP spec: enums (unknown values are kept), bitfields (named
//! accessors), structs and unions (selected by an earlier enum parameter).

/// Accelerometer range code. Dynamic range of all three accelerometer axes (Tables 37 and 60; device specific).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AccelRange(pub u8);

impl AccelRange {
    /// Accelerometer range +-2 g.
    pub const RANGE_2G: Self = Self(0);
    /// Accelerometer range +-4 g.
    pub const RANGE_4G: Self = Self(1);
    /// Accelerometer range +-8 g.
    pub const RANGE_8G: Self = Self(2);
    /// Accelerometer range +-10 g.
    pub const RANGE_10G: Self = Self(3);
    /// Accelerometer range +-15 g.
    pub const RANGE_15G: Self = Self(4);
    /// Accelerometer range +-20 g.
    pub const RANGE_20G: Self = Self(5);
    /// Accelerometer range +-40 g.
    pub const RANGE_40G: Self = Self(6);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("range_2g"),
            1 => Some("range_4g"),
            2 => Some("range_8g"),
            3 => Some("range_10g"),
            4 => Some("range_15g"),
            5 => Some("range_20g"),
            6 => Some("range_40g"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "range_2g" => Some(Self::RANGE_2G),
            "range_4g" => Some(Self::RANGE_4G),
            "range_8g" => Some(Self::RANGE_8G),
            "range_10g" => Some(Self::RANGE_10G),
            "range_15g" => Some(Self::RANGE_15G),
            "range_20g" => Some(Self::RANGE_20G),
            "range_40g" => Some(Self::RANGE_40G),
            _ => None,
        }
    }
}

impl core::fmt::Debug for AccelRange {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "AccelRange({} {})", self.0, name),
            None => write!(f, "AccelRange({})", self.0),
        }
    }
}

impl crate::wire::Wire for AccelRange {
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
impl crate::json_read::FromJson for AccelRange {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// UART baud rate. Baud rates the UART accepts, sent as their value (Table 20).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BaudRate(pub u32);

impl BaudRate {
    /// 9600 baud (0x00002580).
    pub const BAUD_9600: Self = Self(9600);
    /// 19200 baud (0x00004B00).
    pub const BAUD_19200: Self = Self(19200);
    /// 115200 baud (0x0001C200).
    pub const BAUD_115200: Self = Self(115200);
    /// 230400 baud (0x00038400).
    pub const BAUD_230400: Self = Self(230400);
    /// 460800 baud (0x00070800).
    pub const BAUD_460800: Self = Self(460800);
    /// 921600 baud (0x000E1000).
    pub const BAUD_921600: Self = Self(921600);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            9600 => Some("baud_9600"),
            19200 => Some("baud_19200"),
            115200 => Some("baud_115200"),
            230400 => Some("baud_230400"),
            460800 => Some("baud_460800"),
            921600 => Some("baud_921600"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "baud_9600" => Some(Self::BAUD_9600),
            "baud_19200" => Some(Self::BAUD_19200),
            "baud_115200" => Some(Self::BAUD_115200),
            "baud_230400" => Some(Self::BAUD_230400),
            "baud_460800" => Some(Self::BAUD_460800),
            "baud_921600" => Some(Self::BAUD_921600),
            _ => None,
        }
    }
}

impl core::fmt::Debug for BaudRate {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "BaudRate({} {})", self.0, name),
            None => write!(f, "BaudRate({})", self.0),
        }
    }
}

impl crate::wire::Wire for BaudRate {
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
impl crate::json_read::FromJson for BaudRate {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u32 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Error code. Second data byte of the ack field (Table 2).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ErrorCode(pub u8);

impl ErrorCode {
    /// The message was received without error.
    pub const OK: Self = Self(0);
    /// The checksum sent with the previous message does not calculate to the correct value.
    pub const CHECKSUM_ERROR: Self = Self(1);
    /// The previous message contained an invalid message type.
    pub const INVALID_MESSAGE_TYPE: Self = Self(2);
    /// The previous message had an invalid message code.
    pub const INVALID_MESSAGE_CODE: Self = Self(3);
    /// A parameter in the previous message is not valid.
    pub const INVALID_PARAMETER: Self = Self(4);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("ok"),
            1 => Some("checksum_error"),
            2 => Some("invalid_message_type"),
            3 => Some("invalid_message_code"),
            4 => Some("invalid_parameter"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "ok" => Some(Self::OK),
            "checksum_error" => Some(Self::CHECKSUM_ERROR),
            "invalid_message_type" => Some(Self::INVALID_MESSAGE_TYPE),
            "invalid_message_code" => Some(Self::INVALID_MESSAGE_CODE),
            "invalid_parameter" => Some(Self::INVALID_PARAMETER),
            _ => None,
        }
    }
}

impl core::fmt::Debug for ErrorCode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "ErrorCode({} {})", self.0, name),
            None => write!(f, "ErrorCode({})", self.0),
        }
    }
}

impl crate::wire::Wire for ErrorCode {
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
impl crate::json_read::FromJson for ErrorCode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Filter bandwidth control code. Digital filter setting: disabled, or an IIR low-pass with the given -3 dB cutoff. The cutoffs are device specific; these are the MS-IMU3020's (Table 24).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FilterBandwidth(pub u8);

impl FilterBandwidth {
    /// Disable filter.
    pub const DISABLED: Self = Self(0);
    /// IIR filter, -3 dB at 25 Hz.
    pub const IIR_25HZ: Self = Self(1);
    /// IIR filter, -3 dB at 50 Hz.
    pub const IIR_50HZ: Self = Self(2);
    /// IIR filter, -3 dB at 75 Hz.
    pub const IIR_75HZ: Self = Self(3);
    /// IIR filter, -3 dB at 100 Hz.
    pub const IIR_100HZ: Self = Self(4);
    /// IIR filter, -3 dB at 10 Hz.
    pub const IIR_10HZ: Self = Self(5);
    /// IIR filter, -3 dB at 150 Hz.
    pub const IIR_150HZ: Self = Self(6);
    /// IIR filter, -3 dB at 200 Hz.
    pub const IIR_200HZ: Self = Self(7);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("disabled"),
            1 => Some("iir_25hz"),
            2 => Some("iir_50hz"),
            3 => Some("iir_75hz"),
            4 => Some("iir_100hz"),
            5 => Some("iir_10hz"),
            6 => Some("iir_150hz"),
            7 => Some("iir_200hz"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "disabled" => Some(Self::DISABLED),
            "iir_25hz" => Some(Self::IIR_25HZ),
            "iir_50hz" => Some(Self::IIR_50HZ),
            "iir_75hz" => Some(Self::IIR_75HZ),
            "iir_100hz" => Some(Self::IIR_100HZ),
            "iir_10hz" => Some(Self::IIR_10HZ),
            "iir_150hz" => Some(Self::IIR_150HZ),
            "iir_200hz" => Some(Self::IIR_200HZ),
            _ => None,
        }
    }
}

impl core::fmt::Debug for FilterBandwidth {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FilterBandwidth({} {})", self.0, name),
            None => write!(f, "FilterBandwidth({})", self.0),
        }
    }
}

impl crate::wire::Wire for FilterBandwidth {
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
impl crate::json_read::FromJson for FilterBandwidth {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Function code. First data byte of the configuration messages (0x0201, 0x0203-0x0205, 0x0207-0x020D): chooses what the message does.
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FunctionCode(pub u8);

impl FunctionCode {
    /// Use new settings.
    pub const WRITE: Self = Self(1);
    /// Request current settings.
    pub const READ: Self = Self(2);
    /// Save current settings as startup settings.
    pub const SAVE: Self = Self(3);
    /// Load saved startup settings.
    pub const LOAD: Self = Self(4);
    /// Reset to default settings.
    pub const DEFAULT: Self = Self(5);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("write"),
            2 => Some("read"),
            3 => Some("save"),
            4 => Some("load"),
            5 => Some("default"),
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
            _ => None,
        }
    }
}

impl core::fmt::Debug for FunctionCode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "FunctionCode({} {})", self.0, name),
            None => write!(f, "FunctionCode({})", self.0),
        }
    }
}

impl crate::wire::Wire for FunctionCode {
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
impl crate::json_read::FromJson for FunctionCode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// GPS correlated time flags. Status of the GPS time correlation (Table 71).
///
/// Bits the spec does not name are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct GpsTimeFlags(pub u16);

impl GpsTimeFlags {
    /// Mask of `pps_received` (bit 0).
    pub const PPS_RECEIVED: u16 = 0x0001;
    /// Mask of `time_set` (bit 1).
    pub const TIME_SET: u16 = 0x0002;
    /// Mask of `time_not_set` (bit 2).
    pub const TIME_NOT_SET: u16 = 0x0004;
    /// Mask of `pps_lost` (bit 3).
    pub const PPS_LOST: u16 = 0x0008;
    /// Mask of `reserved` (bits 4..=15).
    pub const RESERVED: u16 = 0xFFF0;

    /// GPS 1 PPS received: set for one sample after the pulse (only once GPS time is set). (bit 0)
    pub const fn pps_received(self) -> bool {
        self.0 & Self::PPS_RECEIVED != 0
    }

    /// Sets or clears `pps_received` (bit 0).
    pub fn set_pps_received(&mut self, v: bool) {
        if v {
            self.0 |= Self::PPS_RECEIVED;
        } else {
            self.0 &= !Self::PPS_RECEIVED;
        }
    }

    /// GPS time was set: set for one sample after the message that set it. (bit 1)
    pub const fn time_set(self) -> bool {
        self.0 & Self::TIME_SET != 0
    }

    /// Sets or clears `time_set` (bit 1).
    pub fn set_time_set(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIME_SET;
        } else {
            self.0 &= !Self::TIME_SET;
        }
    }

    /// No GPS time set: the time counts from week 0, time 0 on the internal clock. (bit 2)
    pub const fn time_not_set(self) -> bool {
        self.0 & Self::TIME_NOT_SET != 0
    }

    /// Sets or clears `time_not_set` (bit 2).
    pub fn set_time_not_set(&mut self, v: bool) {
        if v {
            self.0 |= Self::TIME_NOT_SET;
        } else {
            self.0 &= !Self::TIME_NOT_SET;
        }
    }

    /// 1 PPS lost: more than 1 s without a pulse since the time was set; the internal clock carries on. (bit 3)
    pub const fn pps_lost(self) -> bool {
        self.0 & Self::PPS_LOST != 0
    }

    /// Sets or clears `pps_lost` (bit 3).
    pub fn set_pps_lost(&mut self, v: bool) {
        if v {
            self.0 |= Self::PPS_LOST;
        } else {
            self.0 &= !Self::PPS_LOST;
        }
    }

    /// Reserved. Reserved. (bits 4..=15)
    pub const fn reserved(self) -> u16 {
        (self.0 & Self::RESERVED) >> 4
    }

    /// Sets `reserved` (bits 4..=15); higher bits of `v` are ignored.
    pub fn set_reserved(&mut self, v: u16) {
        self.0 = (self.0 & !Self::RESERVED) | ((v << 4) & Self::RESERVED);
    }
}

impl crate::wire::Wire for GpsTimeFlags {
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
impl crate::json_read::FromJson for GpsTimeFlags {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u16 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Gyroscope range code. Dynamic range of all three gyroscope axes (Table 41; device specific).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GyroRange(pub u8);

impl GyroRange {
    /// Gyroscope range +-120 deg/s.
    pub const RANGE_120DPS: Self = Self(1);
    /// Gyroscope range +-240 deg/s.
    pub const RANGE_240DPS: Self = Self(2);
    /// Gyroscope range +-480 deg/s.
    pub const RANGE_480DPS: Self = Self(3);
    /// Gyroscope range +-960 deg/s.
    pub const RANGE_960DPS: Self = Self(4);
    /// Gyroscope range +-1920 deg/s.
    pub const RANGE_1920DPS: Self = Self(5);
    /// Gyroscope range +-75 deg/s.
    pub const RANGE_75DPS: Self = Self(6);
    /// Gyroscope range +-200 deg/s.
    pub const RANGE_200DPS: Self = Self(7);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            1 => Some("range_120dps"),
            2 => Some("range_240dps"),
            3 => Some("range_480dps"),
            4 => Some("range_960dps"),
            5 => Some("range_1920dps"),
            6 => Some("range_75dps"),
            7 => Some("range_200dps"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "range_120dps" => Some(Self::RANGE_120DPS),
            "range_240dps" => Some(Self::RANGE_240DPS),
            "range_480dps" => Some(Self::RANGE_480DPS),
            "range_960dps" => Some(Self::RANGE_960DPS),
            "range_1920dps" => Some(Self::RANGE_1920DPS),
            "range_75dps" => Some(Self::RANGE_75DPS),
            "range_200dps" => Some(Self::RANGE_200DPS),
            _ => None,
        }
    }
}

impl core::fmt::Debug for GyroRange {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "GyroRange({} {})", self.0, name),
            None => write!(f, "GyroRange({})", self.0),
        }
    }
}

impl crate::wire::Wire for GyroRange {
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
impl crate::json_read::FromJson for GyroRange {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Message identifier. One supported message: "2 bytes for each message supported indicating the Message Type in the MSB and the Message ID Code in the LSB" (line 200).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MessageId {
    /// Message type (0x01, 0x02, 0xA2, ...).
    pub message_type: u8,
    /// Message code within the type.
    pub message_code: u8,
}

impl Default for MessageId {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MessageId {
    const ZERO: Self = Self {
        message_type: <u8 as crate::wire::Wire>::ZERO,
        message_code: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_message_type =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("message_type"))?;
        let p_message_code =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("message_code"))?;
        Ok(Self {
            message_type: p_message_type,
            message_code: p_message_code,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.message_type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("message_type"))?;
        let v = &self.message_code;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("message_code"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.message_type;
        crate::json::key(w, &mut first, "message_type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.message_code;
        crate::json::key(w, &mut first, "message_code")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MessageId {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["message_type", "message_code"])?;
        let p_message_type = o.req(
            "message_type",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_message_code = o.req(
            "message_code",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            message_type: p_message_type,
            message_code: p_message_code,
        })
    }
}

/// On/off control code. Control code of Data On/Off (Table 48) and XTRIG On/Off (Table 52).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct OnOff(pub u8);

impl OnOff {
    /// Off.
    pub const OFF: Self = Self(0);
    /// On.
    pub const ON: Self = Self(1);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            0 => Some("off"),
            1 => Some("on"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "off" => Some(Self::OFF),
            "on" => Some(Self::ON),
            _ => None,
        }
    }
}

impl core::fmt::Debug for OnOff {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "OnOff({} {})", self.0, name),
            None => write!(f, "OnOff({})", self.0),
        }
    }
}

impl crate::wire::Wire for OnOff {
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
impl crate::json_read::FromJson for OnOff {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}

/// Sensor select code. A measurement to include in the IMU data message: the message code of its 0xA2 data field (Tables 31 and 56).
///
/// Values the spec does not list are kept as they are.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SensorCode(pub u8);

impl SensorCode {
    /// Scaled acceleration vector in g.
    pub const SCALED_ACCEL: Self = Self(129);
    /// Scaled angular rate vector in deg/s.
    pub const SCALED_GYRO: Self = Self(130);
    /// Scaled magnetic field vector in gauss.
    pub const SCALED_MAG: Self = Self(131);
    /// Delta theta vector in radians.
    pub const DELTA_THETA: Self = Self(132);
    /// Delta velocity vector in m/s.
    pub const DELTA_VELOCITY: Self = Self(133);
    /// Scaled pressure in millibar.
    pub const SCALED_PRESSURE: Self = Self(134);
    /// Scaled temperature in degrees Celsius.
    pub const SCALED_TEMPERATURE: Self = Self(135);
    /// GPS correlated time.
    pub const GPS_CORRELATED_TIME: Self = Self(136);
    /// Scaled auxiliary acceleration vector in g (Select Sensors Rev B only).
    pub const SCALED_AUX_ACCEL: Self = Self(137);

    /// Name of the value in the spec, if the spec lists it.
    pub fn name(self) -> Option<&'static str> {
        match self.0 {
            129 => Some("scaled_accel"),
            130 => Some("scaled_gyro"),
            131 => Some("scaled_mag"),
            132 => Some("delta_theta"),
            133 => Some("delta_velocity"),
            134 => Some("scaled_pressure"),
            135 => Some("scaled_temperature"),
            136 => Some("gps_correlated_time"),
            137 => Some("scaled_aux_accel"),
            _ => None,
        }
    }

    /// The value with this name in the spec.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "scaled_accel" => Some(Self::SCALED_ACCEL),
            "scaled_gyro" => Some(Self::SCALED_GYRO),
            "scaled_mag" => Some(Self::SCALED_MAG),
            "delta_theta" => Some(Self::DELTA_THETA),
            "delta_velocity" => Some(Self::DELTA_VELOCITY),
            "scaled_pressure" => Some(Self::SCALED_PRESSURE),
            "scaled_temperature" => Some(Self::SCALED_TEMPERATURE),
            "gps_correlated_time" => Some(Self::GPS_CORRELATED_TIME),
            "scaled_aux_accel" => Some(Self::SCALED_AUX_ACCEL),
            _ => None,
        }
    }
}

impl core::fmt::Debug for SensorCode {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.name() {
            Some(name) => write!(f, "SensorCode({} {})", self.0, name),
            None => write!(f, "SensorCode({})", self.0),
        }
    }
}

impl crate::wire::Wire for SensorCode {
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
impl crate::json_read::FromJson for SensorCode {
    /// The integer value (docs/conformance.md §5: a value name is not accepted, in every
    /// language; `from_name` gives a name's value to the caller's code).
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        <u8 as crate::json_read::FromJson>::from_json(v).map(Self)
    }
}
