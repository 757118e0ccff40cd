//! Base Command Set. Commands common to every MIP device: identify the device, list its descriptors, run built-in tests, idle/resume/reset, and set the GPS time.
//!
//! Descriptor set 0x01 (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x01;

/// Ping. Test communications with a device. The device responds with an ACK if present.
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

/// Set to idle. Turn off all device data streams; suspends streaming or wakes the device from sleep so it can answer status and setup commands. Resume restores the previous mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SetToIdle {}

impl Default for SetToIdle {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SetToIdle {
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
impl crate::json_read::FromJson for SetToIdle {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl SetToIdle {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for SetToIdle {
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "set_to_idle";
}

/// Get device information. Get the device ID strings and firmware version.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetDeviceInfo {}

impl Default for GetDeviceInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetDeviceInfo {
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
impl crate::json_read::FromJson for GetDeviceInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetDeviceInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetDeviceInfo {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_device_info";
}

/// Device information. Reply to Get device information.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceInfo {
    /// Device information.
    pub info: crate::types::DeviceInfo,
}

impl Default for DeviceInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceInfo {
    const ZERO: Self = Self {
        info: <crate::types::DeviceInfo as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(82);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_info =
            <crate::types::DeviceInfo as crate::wire::Wire>::decode(r).map_err(|e| e.at("info"))?;
        Ok(Self { info: p_info })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.info;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("info"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.info;
        crate::json::key(w, &mut first, "info")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["info"])?;
        let p_info = o.req(
            "info",
            <crate::types::DeviceInfo as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { info: p_info })
    }
}

impl DeviceInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceInfo {
    const DESCRIPTOR: u8 = 0x81;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_info";
}

/// Get device descriptor sets. Get the command and data descriptors supported by the device.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetDeviceDescriptors {}

impl Default for GetDeviceDescriptors {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetDeviceDescriptors {
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
impl crate::json_read::FromJson for GetDeviceDescriptors {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetDeviceDescriptors {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetDeviceDescriptors {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_device_descriptors";
}

/// Device descriptors. Array of 16-bit values: the MSB is the descriptor set and the LSB the descriptor. The array runs to the end of the field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceDescriptors {
    /// Supported descriptors, (set << 8) | descriptor.
    pub descriptors: crate::bounded::BoundedVec<u16, 126>,
}

impl Default for DeviceDescriptors {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceDescriptors {
    const ZERO: Self = Self {
        descriptors: <crate::bounded::BoundedVec<u16, 126> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_descriptors = crate::bounded::BoundedVec::<u16, 126>::decode_remaining(r)
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceDescriptors {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["descriptors"])?;
        let p_descriptors = o.req(
            "descriptors",
            <crate::bounded::BoundedVec<u16, 126> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            descriptors: p_descriptors,
        })
    }
}

impl DeviceDescriptors {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for DeviceDescriptors {
    const DESCRIPTOR: u8 = 0x82;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_descriptors";
}

/// Built-in test. Run the device built-in test (BIT). The result is a 32-bit value; 0 means all tests passed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuiltInTest {}

impl Default for BuiltInTest {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BuiltInTest {
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
impl crate::json_read::FromJson for BuiltInTest {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl BuiltInTest {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for BuiltInTest {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "built_in_test";
}

/// Built-in test result. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuiltInTestResultGx5_45 {
    /// BIT error flags; 0 means all tests passed.
    pub flags: crate::types::Gx5BitFlags,
}

impl Default for BuiltInTestResultGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BuiltInTestResultGx5_45 {
    const ZERO: Self = Self {
        flags: <crate::types::Gx5BitFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_flags = <crate::types::Gx5BitFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("flags"))?;
        Ok(Self { flags: p_flags })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.flags;
        crate::json::key(w, &mut first, "flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for BuiltInTestResultGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["flags"])?;
        let p_flags = o.req(
            "flags",
            <crate::types::Gx5BitFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { flags: p_flags })
    }
}

impl BuiltInTestResultGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for BuiltInTestResultGx5_45 {
    const DESCRIPTOR: u8 = 0x83;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "built_in_test_result";
}

/// Built-in test result. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuiltInTestResultCv7Ins {
    /// BIT result bitfield; 0 means all tests passed.
    pub flags: crate::types::Cv7BitFlags,
}

impl Default for BuiltInTestResultCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BuiltInTestResultCv7Ins {
    const ZERO: Self = Self {
        flags: <crate::types::Cv7BitFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_flags = <crate::types::Cv7BitFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("flags"))?;
        Ok(Self { flags: p_flags })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.flags;
        crate::json::key(w, &mut first, "flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for BuiltInTestResultCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["flags"])?;
        let p_flags = o.req(
            "flags",
            <crate::types::Cv7BitFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { flags: p_flags })
    }
}

impl BuiltInTestResultCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for BuiltInTestResultCv7Ins {
    const DESCRIPTOR: u8 = 0x83;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "built_in_test_result";
}

/// Built-in test result. Result of the commanded built-in test. The flags are device specific.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BuiltInTestResult {
    /// Layout for device `gx5_45`.
    Gx5_45(BuiltInTestResultGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(BuiltInTestResultCv7Ins),
}

impl BuiltInTestResult {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x83;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "built_in_test_result";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <BuiltInTestResultGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <BuiltInTestResultCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first = match <BuiltInTestResultGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <BuiltInTestResultCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <BuiltInTestResultGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <BuiltInTestResultCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field built_in_test_result has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Resume. Place the device back into the mode it was in before Set to idle (default mode if none).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resume {}

impl Default for Resume {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Resume {
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
impl crate::json_read::FromJson for Resume {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl Resume {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for Resume {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "resume";
}

/// Get extended device descriptor sets. Get the descriptors supported in addition to those returned by Get device descriptor sets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetExtendedDescriptors {}

impl Default for GetExtendedDescriptors {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetExtendedDescriptors {
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
impl crate::json_read::FromJson for GetExtendedDescriptors {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetExtendedDescriptors {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GetExtendedDescriptors {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "get_extended_descriptors";
}

/// Extended device descriptors. Array of 16-bit descriptors (MSB set, LSB descriptor) running to the end of the field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExtendedDescriptors {
    /// Supported extended descriptors, (set << 8) | descriptor.
    pub descriptors: crate::bounded::BoundedVec<u16, 126>,
}

impl Default for ExtendedDescriptors {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ExtendedDescriptors {
    const ZERO: Self = Self {
        descriptors: <crate::bounded::BoundedVec<u16, 126> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_descriptors = crate::bounded::BoundedVec::<u16, 126>::decode_remaining(r)
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ExtendedDescriptors {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["descriptors"])?;
        let p_descriptors = o.req(
            "descriptors",
            <crate::bounded::BoundedVec<u16, 126> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            descriptors: p_descriptors,
        })
    }
}

impl ExtendedDescriptors {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for ExtendedDescriptors {
    const DESCRIPTOR: u8 = 0x86;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "extended_descriptors";
}

/// Continuous built-in test. Report the result of the continuous built-in test (non-disruptive).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContinuousBit {}

impl Default for ContinuousBit {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ContinuousBit {
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
impl crate::json_read::FromJson for ContinuousBit {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl ContinuousBit {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for ContinuousBit {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "continuous_bit";
}

/// Continuous built-in test result. Device-specific 128-bit bitfield, least-significant byte first: bit 0 is bit 0 of result\[0\], bit 127 is bit 7 of result\[15\].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContinuousBitResult {
    /// Continuous BIT bit map (16 bytes, least-significant byte first), as in system data 0xA0,0x01.
    pub result: crate::types::Cv7ContinuousBit,
}

impl Default for ContinuousBitResult {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ContinuousBitResult {
    const ZERO: Self = Self {
        result: <crate::types::Cv7ContinuousBit as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_result = <crate::types::Cv7ContinuousBit as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("result"))?;
        Ok(Self { result: p_result })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.result;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("result"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.result;
        crate::json::key(w, &mut first, "result")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ContinuousBitResult {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["result"])?;
        let p_result = o.req(
            "result",
            <crate::types::Cv7ContinuousBit as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { result: p_result })
    }
}

impl ContinuousBitResult {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for ContinuousBitResult {
    const DESCRIPTOR: u8 = 0x88;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "continuous_bit_result";
}

/// Comm port speed. Controls the baud rate of a port. The device waits up to 250 ms for pending data before applying the change; send it alone, with the device idle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CommPortSpeed {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Port ID (0x01 main, 0x11-0x13 UART1-3, 0x21 USB); 0 means all ports for save, load and default. Sent for: write, read, save, load, default.
    pub port: u8,
    /// Port baud rate; must be a supported rate. Units: bit/s. Sent for: write.
    pub baud: Option<u32>,
}

impl Default for CommPortSpeed {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CommPortSpeed {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        port: <u8 as crate::wire::Wire>::ZERO,
        baud: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_port = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("port"))?;
        let p_baud = if r.left() > 0 {
            Some(<u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("baud"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            port: p_port,
            baud: p_baud,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.port;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("port"))?;
        if let Some(v) = &self.baud {
            optionals.present("baud")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("baud"))?;
        } else {
            optionals.absent("baud");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.port;
        crate::json::key(w, &mut first, "port")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.baud {
            crate::json::key(w, &mut first, "baud")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CommPortSpeed {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "port", "baud"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_port = o.req("port", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_baud = o.opt("baud", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            port: p_port,
            baud: p_baud,
        })
    }
}

impl CommPortSpeed {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for CommPortSpeed {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "comm_port_speed";
}

/// Comm port speed (response). Current baud rate of a port.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CommPortSpeedResponse {
    /// Port ID (0x01 main, 0x11-0x13 UART1-3, 0x21 USB).
    pub port: u8,
    /// Port baud rate. Units: bit/s.
    pub baud: u32,
}

impl Default for CommPortSpeedResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CommPortSpeedResponse {
    const ZERO: Self = Self {
        port: <u8 as crate::wire::Wire>::ZERO,
        baud: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_port = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("port"))?;
        let p_baud = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("baud"))?;
        Ok(Self {
            port: p_port,
            baud: p_baud,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.port;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("port"))?;
        let v = &self.baud;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("baud"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.port;
        crate::json::key(w, &mut first, "port")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.baud;
        crate::json::key(w, &mut first, "baud")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CommPortSpeedResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["port", "baud"])?;
        let p_port = o.req("port", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_baud = o.req("baud", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            port: p_port,
            baud: p_baud,
        })
    }
}

impl CommPortSpeedResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for CommPortSpeedResponse {
    const DESCRIPTOR: u8 = 0x89;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "comm_port_speed_response";
}

/// GPS time update. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsTimeUpdateGx5_45 {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Which time value: 1 GPS week number, 2 GPS seconds. Sent for: write, read, write_no_ack.
    pub field_id: crate::types::GpsTimeField,
    /// New week number or seconds, depending on field_id. Sent for: write, write_no_ack.
    pub value: Option<u32>,
}

impl Default for GpsTimeUpdateGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsTimeUpdateGx5_45 {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        field_id: <crate::types::GpsTimeField as crate::wire::Wire>::ZERO,
        value: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_field_id = <crate::types::GpsTimeField as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("field_id"))?;
        let p_value = if r.left() > 0 {
            Some(<u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("value"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            field_id: p_field_id,
            value: p_value,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.field_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("field_id"))?;
        if let Some(v) = &self.value {
            optionals.present("value")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("value"))?;
        } else {
            optionals.absent("value");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.field_id;
        crate::json::key(w, &mut first, "field_id")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.value {
            crate::json::key(w, &mut first, "value")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpsTimeUpdateGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "field_id", "value"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_field_id = o.req(
            "field_id",
            <crate::types::GpsTimeField as crate::json_read::FromJson>::from_json,
        )?;
        let p_value = o.opt("value", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            field_id: p_field_id,
            value: p_value,
        })
    }
}

impl GpsTimeUpdateGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GpsTimeUpdateGx5_45 {
    const DESCRIPTOR: u8 = 0x72;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "gps_time_update";
}

/// GPS time update. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsTimeUpdateCv7Ins {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Determines how to interpret value. Sent for: write.
    pub field_id: crate::types::GpsTimeField,
    /// Week number or time of week, depending on field_id. Sent for: write.
    pub value: u32,
}

impl Default for GpsTimeUpdateCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsTimeUpdateCv7Ins {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        field_id: <crate::types::GpsTimeField as crate::wire::Wire>::ZERO,
        value: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_field_id = <crate::types::GpsTimeField as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("field_id"))?;
        let p_value = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("value"))?;
        Ok(Self {
            function: p_function,
            field_id: p_field_id,
            value: p_value,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.field_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("field_id"))?;
        let v = &self.value;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("value"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.field_id;
        crate::json::key(w, &mut first, "field_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.value;
        crate::json::key(w, &mut first, "value")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpsTimeUpdateCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "field_id", "value"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_field_id = o.req(
            "field_id",
            <crate::types::GpsTimeField as crate::json_read::FromJson>::from_json,
        )?;
        let p_value = o.req("value", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            field_id: p_field_id,
            value: p_value,
        })
    }
}

impl GpsTimeUpdateCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GpsTimeUpdateCv7Ins {
    const DESCRIPTOR: u8 = 0x72;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "gps_time_update";
}

/// GPS time update. Set the device's internal GPS time (week number or time of week). Combined with a PPS input this synchronises the device's timestamps with an external GPS clock.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GpsTimeUpdate {
    /// Layout for device `gx5_45`.
    Gx5_45(GpsTimeUpdateGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(GpsTimeUpdateCv7Ins),
}

impl GpsTimeUpdate {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x72;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "gps_time_update";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <GpsTimeUpdateGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <GpsTimeUpdateCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first = match <GpsTimeUpdateGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <GpsTimeUpdateCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <GpsTimeUpdateGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <GpsTimeUpdateCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field gps_time_update has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Current GPS week. Reply to GPS time update read with field selector 1 (week).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsWeek {
    /// Current GPS week value. Units: weeks.
    pub week: u32,
}

impl Default for GpsWeek {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsWeek {
    const ZERO: Self = Self {
        week: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_week = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week"))?;
        Ok(Self { week: p_week })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.week;
        crate::json::key(w, &mut first, "week")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpsWeek {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["week"])?;
        let p_week = o.req("week", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { week: p_week })
    }
}

impl GpsWeek {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GpsWeek {
    const DESCRIPTOR: u8 = 0x84;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "gps_week";
}

/// Current GPS seconds. Reply to GPS time update read with field selector 2 (seconds).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsSeconds {
    /// Current GPS seconds value. Units: s.
    pub seconds: u32,
}

impl Default for GpsSeconds {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsSeconds {
    const ZERO: Self = Self {
        seconds: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_seconds = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("seconds"))?;
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
impl crate::json_read::FromJson for GpsSeconds {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["seconds"])?;
        let p_seconds = o.req("seconds", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { seconds: p_seconds })
    }
}

impl GpsSeconds {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x01;
}

impl crate::wire::Layout for GpsSeconds {
    const DESCRIPTOR: u8 = 0x85;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "gps_seconds";
}

/// Device reset. Resets the device. The device ACKs and then immediately resets.
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
    const DESCRIPTOR: u8 = 0x7E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x01);
    const NAME: &'static str = "device_reset";
}

/// A decoded field of set 0x01 (`base`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `ping` (0x01).
    Ping(Ping),
    /// `set_to_idle` (0x02).
    SetToIdle(SetToIdle),
    /// `get_device_info` (0x03).
    GetDeviceInfo(GetDeviceInfo),
    /// `device_info` (0x81).
    DeviceInfo(DeviceInfo),
    /// `get_device_descriptors` (0x04).
    GetDeviceDescriptors(GetDeviceDescriptors),
    /// `device_descriptors` (0x82).
    DeviceDescriptors(DeviceDescriptors),
    /// `built_in_test` (0x05).
    BuiltInTest(BuiltInTest),
    /// `built_in_test_result` (0x83).
    BuiltInTestResult(BuiltInTestResult),
    /// `resume` (0x06).
    Resume(Resume),
    /// `get_extended_descriptors` (0x07).
    GetExtendedDescriptors(GetExtendedDescriptors),
    /// `extended_descriptors` (0x86).
    ExtendedDescriptors(ExtendedDescriptors),
    /// `continuous_bit` (0x08).
    ContinuousBit(ContinuousBit),
    /// `continuous_bit_result` (0x88).
    ContinuousBitResult(ContinuousBitResult),
    /// `comm_port_speed` (0x09).
    CommPortSpeed(CommPortSpeed),
    /// `comm_port_speed_response` (0x89).
    CommPortSpeedResponse(CommPortSpeedResponse),
    /// `gps_time_update` (0x72).
    GpsTimeUpdate(GpsTimeUpdate),
    /// `gps_week` (0x84).
    GpsWeek(GpsWeek),
    /// `gps_seconds` (0x85).
    GpsSeconds(GpsSeconds),
    /// `device_reset` (0x7E).
    DeviceReset(DeviceReset),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::Ping(_) => 0x01,
            Self::SetToIdle(_) => 0x02,
            Self::GetDeviceInfo(_) => 0x03,
            Self::DeviceInfo(_) => 0x81,
            Self::GetDeviceDescriptors(_) => 0x04,
            Self::DeviceDescriptors(_) => 0x82,
            Self::BuiltInTest(_) => 0x05,
            Self::BuiltInTestResult(_) => 0x83,
            Self::Resume(_) => 0x06,
            Self::GetExtendedDescriptors(_) => 0x07,
            Self::ExtendedDescriptors(_) => 0x86,
            Self::ContinuousBit(_) => 0x08,
            Self::ContinuousBitResult(_) => 0x88,
            Self::CommPortSpeed(_) => 0x09,
            Self::CommPortSpeedResponse(_) => 0x89,
            Self::GpsTimeUpdate(_) => 0x72,
            Self::GpsWeek(_) => 0x84,
            Self::GpsSeconds(_) => 0x85,
            Self::DeviceReset(_) => 0x7E,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Ping(_) => "ping",
            Self::SetToIdle(_) => "set_to_idle",
            Self::GetDeviceInfo(_) => "get_device_info",
            Self::DeviceInfo(_) => "device_info",
            Self::GetDeviceDescriptors(_) => "get_device_descriptors",
            Self::DeviceDescriptors(_) => "device_descriptors",
            Self::BuiltInTest(_) => "built_in_test",
            Self::BuiltInTestResult(_) => "built_in_test_result",
            Self::Resume(_) => "resume",
            Self::GetExtendedDescriptors(_) => "get_extended_descriptors",
            Self::ExtendedDescriptors(_) => "extended_descriptors",
            Self::ContinuousBit(_) => "continuous_bit",
            Self::ContinuousBitResult(_) => "continuous_bit_result",
            Self::CommPortSpeed(_) => "comm_port_speed",
            Self::CommPortSpeedResponse(_) => "comm_port_speed_response",
            Self::GpsTimeUpdate(_) => "gps_time_update",
            Self::GpsWeek(_) => "gps_week",
            Self::GpsSeconds(_) => "gps_seconds",
            Self::DeviceReset(_) => "device_reset",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::Ping(_) => None,
            Self::SetToIdle(_) => None,
            Self::GetDeviceInfo(_) => None,
            Self::DeviceInfo(_) => None,
            Self::GetDeviceDescriptors(_) => None,
            Self::DeviceDescriptors(_) => None,
            Self::BuiltInTest(_) => None,
            Self::BuiltInTestResult(v) => Some(v.device()),
            Self::Resume(_) => None,
            Self::GetExtendedDescriptors(_) => None,
            Self::ExtendedDescriptors(_) => None,
            Self::ContinuousBit(_) => None,
            Self::ContinuousBitResult(_) => None,
            Self::CommPortSpeed(_) => None,
            Self::CommPortSpeedResponse(_) => None,
            Self::GpsTimeUpdate(v) => Some(v.device()),
            Self::GpsWeek(_) => None,
            Self::GpsSeconds(_) => None,
            Self::DeviceReset(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Ping(v) => crate::wire::Layout::encode_data(v, w),
            Self::SetToIdle(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetDeviceInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetDeviceDescriptors(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceDescriptors(v) => crate::wire::Layout::encode_data(v, w),
            Self::BuiltInTest(v) => crate::wire::Layout::encode_data(v, w),
            Self::BuiltInTestResult(v) => v.encode_data(w),
            Self::Resume(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetExtendedDescriptors(v) => crate::wire::Layout::encode_data(v, w),
            Self::ExtendedDescriptors(v) => crate::wire::Layout::encode_data(v, w),
            Self::ContinuousBit(v) => crate::wire::Layout::encode_data(v, w),
            Self::ContinuousBitResult(v) => crate::wire::Layout::encode_data(v, w),
            Self::CommPortSpeed(v) => crate::wire::Layout::encode_data(v, w),
            Self::CommPortSpeedResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsTimeUpdate(v) => v.encode_data(w),
            Self::GpsWeek(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsSeconds(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceReset(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Ping(v) => crate::wire::Wire::write_json(v, w),
            Self::SetToIdle(v) => crate::wire::Wire::write_json(v, w),
            Self::GetDeviceInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::GetDeviceDescriptors(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceDescriptors(v) => crate::wire::Wire::write_json(v, w),
            Self::BuiltInTest(v) => crate::wire::Wire::write_json(v, w),
            Self::BuiltInTestResult(v) => v.write_json(w),
            Self::Resume(v) => crate::wire::Wire::write_json(v, w),
            Self::GetExtendedDescriptors(v) => crate::wire::Wire::write_json(v, w),
            Self::ExtendedDescriptors(v) => crate::wire::Wire::write_json(v, w),
            Self::ContinuousBit(v) => crate::wire::Wire::write_json(v, w),
            Self::ContinuousBitResult(v) => crate::wire::Wire::write_json(v, w),
            Self::CommPortSpeed(v) => crate::wire::Wire::write_json(v, w),
            Self::CommPortSpeedResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsTimeUpdate(v) => v.write_json(w),
            Self::GpsWeek(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsSeconds(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceReset(v) => crate::wire::Wire::write_json(v, w),
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
                Some(<SetToIdle as crate::wire::Layout>::decode_data(data).map(Self::SetToIdle))
            }
            0x03 => Some(
                <GetDeviceInfo as crate::wire::Layout>::decode_data(data).map(Self::GetDeviceInfo),
            ),
            0x81 => {
                Some(<DeviceInfo as crate::wire::Layout>::decode_data(data).map(Self::DeviceInfo))
            }
            0x04 => Some(
                <GetDeviceDescriptors as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetDeviceDescriptors),
            ),
            0x82 => Some(
                <DeviceDescriptors as crate::wire::Layout>::decode_data(data)
                    .map(Self::DeviceDescriptors),
            ),
            0x05 => {
                Some(<BuiltInTest as crate::wire::Layout>::decode_data(data).map(Self::BuiltInTest))
            }
            0x83 => Some(BuiltInTestResult::decode_data(data, device).map(Self::BuiltInTestResult)),
            0x06 => Some(<Resume as crate::wire::Layout>::decode_data(data).map(Self::Resume)),
            0x07 => Some(
                <GetExtendedDescriptors as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetExtendedDescriptors),
            ),
            0x86 => Some(
                <ExtendedDescriptors as crate::wire::Layout>::decode_data(data)
                    .map(Self::ExtendedDescriptors),
            ),
            0x08 => Some(
                <ContinuousBit as crate::wire::Layout>::decode_data(data).map(Self::ContinuousBit),
            ),
            0x88 => Some(
                <ContinuousBitResult as crate::wire::Layout>::decode_data(data)
                    .map(Self::ContinuousBitResult),
            ),
            0x09 => Some(
                <CommPortSpeed as crate::wire::Layout>::decode_data(data).map(Self::CommPortSpeed),
            ),
            0x89 => Some(
                <CommPortSpeedResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::CommPortSpeedResponse),
            ),
            0x72 => Some(GpsTimeUpdate::decode_data(data, device).map(Self::GpsTimeUpdate)),
            0x84 => Some(<GpsWeek as crate::wire::Layout>::decode_data(data).map(Self::GpsWeek)),
            0x85 => {
                Some(<GpsSeconds as crate::wire::Layout>::decode_data(data).map(Self::GpsSeconds))
            }
            0x7E => {
                Some(<DeviceReset as crate::wire::Layout>::decode_data(data).map(Self::DeviceReset))
            }
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
                        <SetToIdle as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SetToIdle),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetDeviceInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetDeviceInfo),
            ),
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceInfo),
            ),
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetDeviceDescriptors as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetDeviceDescriptors),
            ),
            0x82 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceDescriptors as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceDescriptors),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <BuiltInTest as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::BuiltInTest),
            ),
            0x83 => Some(BuiltInTestResult::from_json(device, values).map(Self::BuiltInTestResult)),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Resume as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Resume),
            ),
            0x07 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetExtendedDescriptors as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetExtendedDescriptors),
            ),
            0x86 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExtendedDescriptors as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ExtendedDescriptors),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ContinuousBit as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ContinuousBit),
            ),
            0x88 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ContinuousBitResult as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ContinuousBitResult),
            ),
            0x09 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CommPortSpeed as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CommPortSpeed),
            ),
            0x89 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CommPortSpeedResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CommPortSpeedResponse),
            ),
            0x72 => Some(GpsTimeUpdate::from_json(device, values).map(Self::GpsTimeUpdate)),
            0x84 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsWeek as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsWeek),
            ),
            0x85 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsSeconds as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsSeconds),
            ),
            0x7E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceReset as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceReset),
            ),
            _ => None,
        }
    }
}
