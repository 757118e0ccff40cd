//! System Data Set. Device-level status data (CV7 only); sampled at the system data base rate.
//!
//! Descriptor set 0xA0 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0xA0;

/// Built-in test (streaming continuous BIT). The continuous built-in test result, streamed or polled (the same bits as the Continuous BIT command 0x01,0x08). The bits latch until the next output of this message; some may be set in normal situations (e.g. no GNSS fix yet). Large: stream at a low rate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuiltInTest {
    /// Continuous BIT bit map, 16 bytes, least-significant byte first.
    pub result: crate::types::Cv7ContinuousBit,
}

impl Default for BuiltInTest {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BuiltInTest {
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
impl crate::json_read::FromJson for BuiltInTest {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["result"])?;
        let p_result = o.req(
            "result",
            <crate::types::Cv7ContinuousBit as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { result: p_result })
    }
}

impl BuiltInTest {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA0;
}

impl crate::wire::Layout for BuiltInTest {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA0);
    const NAME: &'static str = "built_in_test";
}

/// Time sync status. Whether the device is synchronised to the PPS signal, and how long ago the last pulse came.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeSyncStatus {
    /// True while PPS sync is valid; false if PPS is disabled or not detected.
    pub time_sync: bool,
    /// Seconds since the last PPS pulse, saturating at 255. Units: s.
    pub last_pps_rcvd: u8,
}

impl Default for TimeSyncStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for TimeSyncStatus {
    const ZERO: Self = Self {
        time_sync: <bool as crate::wire::Wire>::ZERO,
        last_pps_rcvd: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time_sync = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("time_sync"))?;
        let p_last_pps_rcvd =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("last_pps_rcvd"))?;
        Ok(Self {
            time_sync: p_time_sync,
            last_pps_rcvd: p_last_pps_rcvd,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time_sync;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time_sync"))?;
        let v = &self.last_pps_rcvd;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("last_pps_rcvd"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time_sync;
        crate::json::key(w, &mut first, "time_sync")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.last_pps_rcvd;
        crate::json::key(w, &mut first, "last_pps_rcvd")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for TimeSyncStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["time_sync", "last_pps_rcvd"])?;
        let p_time_sync = o.req("time_sync", <bool as crate::json_read::FromJson>::from_json)?;
        let p_last_pps_rcvd = o.req(
            "last_pps_rcvd",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time_sync: p_time_sync,
            last_pps_rcvd: p_last_pps_rcvd,
        })
    }
}

impl TimeSyncStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA0;
}

impl crate::wire::Layout for TimeSyncStatus {
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA0);
    const NAME: &'static str = "time_sync_status";
}

/// GPIO state. States of the user GPIO pins, sampled within one base period of the system data set. For slow signals; pins must be configured with the GPIO feature (0x0C,0x41) to read validly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioState {
    /// One bit per pin; pins that do not exist read 0.
    pub states: crate::types::GpioPinStates,
}

impl Default for GpioState {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioState {
    const ZERO: Self = Self {
        states: <crate::types::GpioPinStates as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_states = <crate::types::GpioPinStates as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("states"))?;
        Ok(Self { states: p_states })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.states;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("states"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.states;
        crate::json::key(w, &mut first, "states")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioState {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["states"])?;
        let p_states = o.req(
            "states",
            <crate::types::GpioPinStates as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { states: p_states })
    }
}

impl GpioState {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA0;
}

impl crate::wire::Layout for GpioState {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA0);
    const NAME: &'static str = "gpio_state";
}

/// A decoded field of set 0xA0 (`system_data`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `built_in_test` (0x01).
    BuiltInTest(BuiltInTest),
    /// `time_sync_status` (0x02).
    TimeSyncStatus(TimeSyncStatus),
    /// `gpio_state` (0x03).
    GpioState(GpioState),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::BuiltInTest(_) => 0x01,
            Self::TimeSyncStatus(_) => 0x02,
            Self::GpioState(_) => 0x03,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::BuiltInTest(_) => "built_in_test",
            Self::TimeSyncStatus(_) => "time_sync_status",
            Self::GpioState(_) => "gpio_state",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::BuiltInTest(_) => None,
            Self::TimeSyncStatus(_) => None,
            Self::GpioState(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::BuiltInTest(v) => crate::wire::Layout::encode_data(v, w),
            Self::TimeSyncStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpioState(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::BuiltInTest(v) => crate::wire::Wire::write_json(v, w),
            Self::TimeSyncStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::GpioState(v) => crate::wire::Wire::write_json(v, w),
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
            0x01 => {
                Some(<BuiltInTest as crate::wire::Layout>::decode_data(data).map(Self::BuiltInTest))
            }
            0x02 => Some(
                <TimeSyncStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::TimeSyncStatus),
            ),
            0x03 => {
                Some(<GpioState as crate::wire::Layout>::decode_data(data).map(Self::GpioState))
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
                        <BuiltInTest as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::BuiltInTest),
            ),
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <TimeSyncStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::TimeSyncStatus),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpioState as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpioState),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x01.
    pub built_in_test: crate::system_data::BuiltInTest,
    /// Field 0x02.
    pub time_sync_status: crate::system_data::TimeSyncStatus,
    /// Field 0x03.
    pub gpio_state: crate::system_data::GpioState,
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

#[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        built_in_test: <crate::system_data::BuiltInTest as crate::wire::Wire>::ZERO,
        time_sync_status: <crate::system_data::TimeSyncStatus as crate::wire::Wire>::ZERO,
        gpio_state: <crate::system_data::GpioState as crate::wire::Wire>::ZERO,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
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
            0x01 | 0x02 | 0x03 | 0xD0 | 0xD3 | 0xD4 | 0xD5 | 0xD6 | 0xD7 | 0xD8
        )
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode_member(&mut self, descriptor: u8, data: &[u8]) -> bool {
        match descriptor {
            0x01 => crate::packets::decode_into(data, &mut self.built_in_test),
            0x02 => match <&[u8; 2]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) if d[0] <= 1 => {
                    let s = &mut self.time_sync_status;
                    s.time_sync = crate::packets::ld(d, 0);
                    s.last_pps_rcvd = crate::packets::ld(d, 1);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.time_sync_status),
            },
            0x03 => match <&[u8; 1]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gpio_state;
                    s.states = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gpio_state),
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
            0x01 => Some(crate::FieldValue::SystemData(
                crate::system_data::SetField::BuiltInTest(self.built_in_test),
            )),
            0x02 => Some(crate::FieldValue::SystemData(
                crate::system_data::SetField::TimeSyncStatus(self.time_sync_status),
            )),
            0x03 => Some(crate::FieldValue::SystemData(
                crate::system_data::SetField::GpioState(self.gpio_state),
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
#[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
