//! Base Messages. Identify the device (supported messages, model, serial number, firmware, calibration date), ping and reset it, and correlate its timestamps with GPS time.
//!
//! Descriptor set 0x01 (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x01;

/// Ping. Check that the device is responsive; it answers with the ack.
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
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "ping";
}

/// Get device messages. Ask which messages the device supports.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetDeviceMessages {}

impl Default for GetDeviceMessages {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetDeviceMessages {
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
impl crate::json_read::FromJson for GetDeviceMessages {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetDeviceMessages {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetDeviceMessages {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_device_messages";
}

/// Device messages. The supported messages, two bytes each (message type, then message code).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceMessages {
    /// Supported messages ("2 * number of commands in bytes").
    pub messages: crate::bounded::BoundedVec<crate::types::MessageId, 126>,
}

impl Default for DeviceMessages {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceMessages {
    const ZERO: Self = Self {
        messages:
            <crate::bounded::BoundedVec<crate::types::MessageId, 126> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_messages =
            crate::bounded::BoundedVec::<crate::types::MessageId, 126>::decode_remaining(r)
                .map_err(|e| e.at("messages"))?;
        Ok(Self {
            messages: p_messages,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.messages;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("messages"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.messages;
        crate::json::key(w, &mut first, "messages")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceMessages {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["messages"])?;
        let p_messages = o.req("messages", <crate::bounded::BoundedVec<crate::types::MessageId, 126> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            messages: p_messages,
        })
    }
}

impl DeviceMessages {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceMessages {
    const DESCRIPTOR: u8 = 0x83;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_messages";
}

/// Device reset. Reset the device; the reset happens right after the ack is sent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceReset {}

impl Default for DeviceReset {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceReset {
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
impl crate::json_read::FromJson for DeviceReset {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl DeviceReset {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceReset {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_reset";
}

/// Get device model. Ask for the device model number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetDeviceModel {}

impl Default for GetDeviceModel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetDeviceModel {
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
impl crate::json_read::FromJson for GetDeviceModel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetDeviceModel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetDeviceModel {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_device_model";
}

/// Device model. The model number, 16 characters, right-justified and padded with spaces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceModel {
    /// Device model, e.g. " MS_IMU3020".
    pub model: crate::wire::Str<16>,
}

impl Default for DeviceModel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceModel {
    const ZERO: Self = Self {
        model: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_model =
            <crate::wire::Str<16> as crate::wire::Wire>::decode(r).map_err(|e| e.at("model"))?;
        Ok(Self { model: p_model })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.model;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("model"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.model;
        crate::json::key(w, &mut first, "model")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceModel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["model"])?;
        let p_model = o.req(
            "model",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { model: p_model })
    }
}

impl DeviceModel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceModel {
    const DESCRIPTOR: u8 = 0x85;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_model";
}

/// Get device serial number. Ask for the device serial number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetDeviceSn {}

impl Default for GetDeviceSn {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetDeviceSn {
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
impl crate::json_read::FromJson for GetDeviceSn {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetDeviceSn {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetDeviceSn {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_device_sn";
}

/// Device serial number. The serial number, 16 characters, right-justified and padded with spaces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceSn {
    /// Serial number, e.g. " 20268".
    pub serial_number: crate::wire::Str<16>,
}

impl Default for DeviceSn {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceSn {
    const ZERO: Self = Self {
        serial_number: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_serial_number = <crate::wire::Str<16> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("serial_number"))?;
        Ok(Self {
            serial_number: p_serial_number,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.serial_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("serial_number"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.serial_number;
        crate::json::key(w, &mut first, "serial_number")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceSn {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["serial_number"])?;
        let p_serial_number = o.req(
            "serial_number",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            serial_number: p_serial_number,
        })
    }
}

impl DeviceSn {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceSn {
    const DESCRIPTOR: u8 = 0x86;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_sn";
}

/// Get device firmware. Ask for the firmware revision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetDeviceFw {}

impl Default for GetDeviceFw {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetDeviceFw {
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
impl crate::json_read::FromJson for GetDeviceFw {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetDeviceFw {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetDeviceFw {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_device_fw";
}

/// Device firmware revision. The firmware revision, 16 characters, right-justified and padded with spaces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceFw {
    /// Firmware revision, e.g. " R_1_2_3".
    pub firmware: crate::wire::Str<16>,
}

impl Default for DeviceFw {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceFw {
    const ZERO: Self = Self {
        firmware: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_firmware =
            <crate::wire::Str<16> as crate::wire::Wire>::decode(r).map_err(|e| e.at("firmware"))?;
        Ok(Self {
            firmware: p_firmware,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.firmware;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("firmware"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.firmware;
        crate::json::key(w, &mut first, "firmware")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceFw {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["firmware"])?;
        let p_firmware = o.req(
            "firmware",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            firmware: p_firmware,
        })
    }
}

impl DeviceFw {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceFw {
    const DESCRIPTOR: u8 = 0x87;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_fw";
}

/// Get device calibration date. Ask for the date the device was calibrated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetDeviceCal {}

impl Default for GetDeviceCal {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetDeviceCal {
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
impl crate::json_read::FromJson for GetDeviceCal {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetDeviceCal {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetDeviceCal {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_device_cal";
}

/// Device calibration date. The calibration date as MM-DD-YYYY, 16 characters, right-justified and padded with spaces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceCal {
    /// Calibration date MM-DD-YYYY, e.g. " 05-08-2015".
    pub date: crate::wire::Str<16>,
}

impl Default for DeviceCal {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceCal {
    const ZERO: Self = Self {
        date: <crate::wire::Str<16> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_date =
            <crate::wire::Str<16> as crate::wire::Wire>::decode(r).map_err(|e| e.at("date"))?;
        Ok(Self { date: p_date })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.date;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("date"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.date;
        crate::json::key(w, &mut first, "date")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceCal {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["date"])?;
        let p_date = o.req(
            "date",
            <crate::wire::Str<16> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { date: p_date })
    }
}

impl DeviceCal {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceCal {
    const DESCRIPTOR: u8 = 0x88;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_cal";
}

/// Correlate GPS time. Set the GPS week and time of week that the next 1-PPS pulse on the interface connector marks; send it right after the pulse. Any processor time in GPS format may stand in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CorrelateGpsTime {
    /// GPS week number. Units: weeks.
    pub week: u16,
    /// GPS time of week in whole seconds. Units: s.
    pub seconds: u32,
}

impl Default for CorrelateGpsTime {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CorrelateGpsTime {
    const ZERO: Self = Self {
        week: <u16 as crate::wire::Wire>::ZERO,
        seconds: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_week = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week"))?;
        let p_seconds = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("seconds"))?;
        Ok(Self {
            week: p_week,
            seconds: p_seconds,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week"))?;
        let v = &self.seconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("seconds"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.week;
        crate::json::key(w, &mut first, "week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.seconds;
        crate::json::key(w, &mut first, "seconds")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CorrelateGpsTime {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["week", "seconds"])?;
        let p_week = o.req("week", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_seconds = o.req("seconds", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            week: p_week,
            seconds: p_seconds,
        })
    }
}

impl CorrelateGpsTime {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for CorrelateGpsTime {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "correlate_gps_time";
}

/// A decoded field of set 0x01 (`base`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `ping` (0x02).
    Ping(Ping),
    /// `get_device_messages` (0x03).
    GetDeviceMessages(GetDeviceMessages),
    /// `device_messages` (0x83).
    DeviceMessages(DeviceMessages),
    /// `device_reset` (0x04).
    DeviceReset(DeviceReset),
    /// `get_device_model` (0x05).
    GetDeviceModel(GetDeviceModel),
    /// `device_model` (0x85).
    DeviceModel(DeviceModel),
    /// `get_device_sn` (0x06).
    GetDeviceSn(GetDeviceSn),
    /// `device_sn` (0x86).
    DeviceSn(DeviceSn),
    /// `get_device_fw` (0x07).
    GetDeviceFw(GetDeviceFw),
    /// `device_fw` (0x87).
    DeviceFw(DeviceFw),
    /// `get_device_cal` (0x08).
    GetDeviceCal(GetDeviceCal),
    /// `device_cal` (0x88).
    DeviceCal(DeviceCal),
    /// `correlate_gps_time` (0x09).
    CorrelateGpsTime(CorrelateGpsTime),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::Ping(_) => 0x02,
            Self::GetDeviceMessages(_) => 0x03,
            Self::DeviceMessages(_) => 0x83,
            Self::DeviceReset(_) => 0x04,
            Self::GetDeviceModel(_) => 0x05,
            Self::DeviceModel(_) => 0x85,
            Self::GetDeviceSn(_) => 0x06,
            Self::DeviceSn(_) => 0x86,
            Self::GetDeviceFw(_) => 0x07,
            Self::DeviceFw(_) => 0x87,
            Self::GetDeviceCal(_) => 0x08,
            Self::DeviceCal(_) => 0x88,
            Self::CorrelateGpsTime(_) => 0x09,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Ping(_) => "ping",
            Self::GetDeviceMessages(_) => "get_device_messages",
            Self::DeviceMessages(_) => "device_messages",
            Self::DeviceReset(_) => "device_reset",
            Self::GetDeviceModel(_) => "get_device_model",
            Self::DeviceModel(_) => "device_model",
            Self::GetDeviceSn(_) => "get_device_sn",
            Self::DeviceSn(_) => "device_sn",
            Self::GetDeviceFw(_) => "get_device_fw",
            Self::DeviceFw(_) => "device_fw",
            Self::GetDeviceCal(_) => "get_device_cal",
            Self::DeviceCal(_) => "device_cal",
            Self::CorrelateGpsTime(_) => "correlate_gps_time",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::Ping(_) => None,
            Self::GetDeviceMessages(_) => None,
            Self::DeviceMessages(_) => None,
            Self::DeviceReset(_) => None,
            Self::GetDeviceModel(_) => None,
            Self::DeviceModel(_) => None,
            Self::GetDeviceSn(_) => None,
            Self::DeviceSn(_) => None,
            Self::GetDeviceFw(_) => None,
            Self::DeviceFw(_) => None,
            Self::GetDeviceCal(_) => None,
            Self::DeviceCal(_) => None,
            Self::CorrelateGpsTime(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Ping(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetDeviceMessages(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceMessages(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceReset(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetDeviceModel(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceModel(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetDeviceSn(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceSn(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetDeviceFw(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceFw(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetDeviceCal(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceCal(v) => crate::wire::Layout::encode_data(v, w),
            Self::CorrelateGpsTime(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Ping(v) => crate::wire::Wire::write_json(v, w),
            Self::GetDeviceMessages(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceMessages(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceReset(v) => crate::wire::Wire::write_json(v, w),
            Self::GetDeviceModel(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceModel(v) => crate::wire::Wire::write_json(v, w),
            Self::GetDeviceSn(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceSn(v) => crate::wire::Wire::write_json(v, w),
            Self::GetDeviceFw(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceFw(v) => crate::wire::Wire::write_json(v, w),
            Self::GetDeviceCal(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceCal(v) => crate::wire::Wire::write_json(v, w),
            Self::CorrelateGpsTime(v) => crate::wire::Wire::write_json(v, w),
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
            0x02 => Some(<Ping as crate::wire::Layout>::decode_data(data).map(Self::Ping)),
            0x03 => Some(
                <GetDeviceMessages as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetDeviceMessages),
            ),
            0x83 => Some(
                <DeviceMessages as crate::wire::Layout>::decode_data(data)
                    .map(Self::DeviceMessages),
            ),
            0x04 => {
                Some(<DeviceReset as crate::wire::Layout>::decode_data(data).map(Self::DeviceReset))
            }
            0x05 => Some(
                <GetDeviceModel as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetDeviceModel),
            ),
            0x85 => {
                Some(<DeviceModel as crate::wire::Layout>::decode_data(data).map(Self::DeviceModel))
            }
            0x06 => {
                Some(<GetDeviceSn as crate::wire::Layout>::decode_data(data).map(Self::GetDeviceSn))
            }
            0x86 => Some(<DeviceSn as crate::wire::Layout>::decode_data(data).map(Self::DeviceSn)),
            0x07 => {
                Some(<GetDeviceFw as crate::wire::Layout>::decode_data(data).map(Self::GetDeviceFw))
            }
            0x87 => Some(<DeviceFw as crate::wire::Layout>::decode_data(data).map(Self::DeviceFw)),
            0x08 => Some(
                <GetDeviceCal as crate::wire::Layout>::decode_data(data).map(Self::GetDeviceCal),
            ),
            0x88 => {
                Some(<DeviceCal as crate::wire::Layout>::decode_data(data).map(Self::DeviceCal))
            }
            0x09 => Some(
                <CorrelateGpsTime as crate::wire::Layout>::decode_data(data)
                    .map(Self::CorrelateGpsTime),
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
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Ping as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Ping),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetDeviceMessages as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetDeviceMessages),
            ),
            0x83 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceMessages as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceMessages),
            ),
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceReset as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceReset),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetDeviceModel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetDeviceModel),
            ),
            0x85 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceModel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceModel),
            ),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetDeviceSn as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetDeviceSn),
            ),
            0x86 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceSn as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceSn),
            ),
            0x07 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetDeviceFw as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetDeviceFw),
            ),
            0x87 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceFw as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceFw),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetDeviceCal as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetDeviceCal),
            ),
            0x88 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceCal as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceCal),
            ),
            0x09 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CorrelateGpsTime as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CorrelateGpsTime),
            ),
            _ => None,
        }
    }
}
