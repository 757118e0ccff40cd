//! Devices, set kinds, dispatch of a field by (set, descriptor) (`docs/conformance.md` §2) and
//! the canonical JSON of packets and skip runs (§4).

use core::fmt::{self, Write};

use crate::error::{DecodeError, DecodeErrorKind, EncodeError};
use crate::fields::{FieldItem, Packet};
use crate::json;
use crate::wire::Writer;

/// A device of the protocol; some fields have a layout per device.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Device {
    /// 3DM-GX5-45 (`gx5_45`).
    Gx5_45,
    /// 3DM-CV7-GNSS/INS (`cv7_ins`).
    Cv7Ins,
}

impl Device {
    /// Every device, in spec order.
    pub const ALL: [Device; 2] = [Device::Gx5_45, Device::Cv7Ins];

    /// Identifier in the spec (`--device ID`, `"device"` in JSON).
    pub fn id(self) -> &'static str {
        match self {
            Device::Gx5_45 => "gx5_45",
            Device::Cv7Ins => "cv7_ins",
        }
    }

    /// Product name.
    pub fn title(self) -> &'static str {
        match self {
            Device::Gx5_45 => "3DM-GX5-45",
            Device::Cv7Ins => "3DM-CV7-GNSS/INS",
        }
    }

    /// File name of the manual that documents the device.
    pub fn manual(self) -> &'static str {
        match self {
            Device::Gx5_45 => "3dm-gx5-45-dcp.txt",
            Device::Cv7Ins => "3dm-cv7-ins-docs.txt",
        }
    }

    /// Every command the device's manual documents: `(set << 8) | descriptor`, ascending (the
    /// IR's `capabilities`).
    pub fn commands(self) -> &'static [u16] {
        match self {
            Device::Gx5_45 => &[
                0x0101, 0x0102, 0x0103, 0x0104, 0x0105, 0x0106, 0x0107, 0x0172, 0x017E, 0x0C01,
                0x0C02, 0x0C03, 0x0C06, 0x0C07, 0x0C08, 0x0C09, 0x0C0A, 0x0C0B, 0x0C11, 0x0C20,
                0x0C21, 0x0C22, 0x0C23, 0x0C24, 0x0C30, 0x0C37, 0x0C38, 0x0C39, 0x0C3A, 0x0C3B,
                0x0C3E, 0x0C40, 0x0C50, 0x0C51, 0x0C64, 0x0D01, 0x0D02, 0x0D03, 0x0D10, 0x0D11,
                0x0D12, 0x0D13, 0x0D14, 0x0D15, 0x0D16, 0x0D17, 0x0D18, 0x0D19, 0x0D1A, 0x0D1B,
                0x0D1C, 0x0D1D, 0x0D1E, 0x0D1F, 0x0D20, 0x0D21, 0x0D22, 0x0D23, 0x0D27, 0x0D28,
                0x0D29, 0x0D2B, 0x0D2C, 0x0D42, 0x0D43, 0x0D44, 0x0D45, 0x0D46, 0x0D47, 0x0D4B,
                0x0D4C, 0x0D4D, 0x7F10,
            ],
            Device::Cv7Ins => &[
                0x0101, 0x0102, 0x0103, 0x0104, 0x0105, 0x0106, 0x0107, 0x0108, 0x0109, 0x0172,
                0x017E, 0x0C04, 0x0C0C, 0x0C0D, 0x0C0E, 0x0C0F, 0x0C10, 0x0C11, 0x0C22, 0x0C28,
                0x0C2A, 0x0C2B, 0x0C2C, 0x0C2D, 0x0C2E, 0x0C2F, 0x0C30, 0x0C31, 0x0C32, 0x0C33,
                0x0C37, 0x0C38, 0x0C39, 0x0C3A, 0x0C3B, 0x0C40, 0x0C41, 0x0C42, 0x0C43, 0x0C50,
                0x0C51, 0x0C52, 0x0C53, 0x0C54, 0x0D01, 0x0D03, 0x0D05, 0x0D13, 0x0D15, 0x0D17,
                0x0D1A, 0x0D1B, 0x0D1C, 0x0D1D, 0x0D1F, 0x0D20, 0x0D28, 0x0D43, 0x0D50, 0x0D52,
                0x0D53, 0x0D54, 0x0D55, 0x0D56, 0x0D61, 0x0D63, 0x0D64, 0x0E01, 0x0E02, 0x0E20,
                0x1301, 0x131F, 0x1321, 0x1322, 0x1323, 0x1328, 0x1329, 0x132A, 0x1331, 0x1332,
                0x1333,
            ],
        }
    }

    /// Every data quantity the device's manual documents: `(set << 8) | descriptor`, ascending.
    pub fn data(self) -> &'static [u16] {
        match self {
            Device::Gx5_45 => &[
                0x8004, 0x8005, 0x8006, 0x8007, 0x8008, 0x8009, 0x800A, 0x800C, 0x8010, 0x8011,
                0x8012, 0x8017, 0x8103, 0x8104, 0x8105, 0x8106, 0x8107, 0x8108, 0x8109, 0x810A,
                0x810B, 0x810C, 0x810D, 0x810E, 0x810F, 0x8201, 0x8202, 0x8203, 0x8204, 0x8205,
                0x8206, 0x8207, 0x8208, 0x8209, 0x820A, 0x820B, 0x820C, 0x820D, 0x820E, 0x820F,
                0x8210, 0x8211, 0x8212, 0x8213, 0x8214, 0x8215, 0x8216, 0x8217, 0x8218, 0x8219,
                0x821C, 0x8220, 0x8221, 0x8225, 0x8226, 0x8228, 0x8229, 0x8230, 0x8231,
            ],
            Device::Cv7Ins => &[
                0x8004, 0x8005, 0x8006, 0x8007, 0x8008, 0x8009, 0x800A, 0x800C, 0x8012, 0x8014,
                0x8017, 0x8018, 0x8040, 0x8201, 0x8202, 0x8203, 0x8204, 0x8205, 0x8206, 0x8207,
                0x8208, 0x8209, 0x820A, 0x820B, 0x820C, 0x820D, 0x820E, 0x8210, 0x8211, 0x8212,
                0x8213, 0x8215, 0x821C, 0x8221, 0x8234, 0x8235, 0x8236, 0x8237, 0x8240, 0x8241,
                0x8242, 0x8243, 0x8246, 0x8247, 0x8248, 0x8249, 0x8250, 0x8251, 0x9103, 0x9104,
                0x9105, 0x9106, 0x9107, 0x9108, 0x9109, 0x910B, 0x910D, 0x9110, 0x9111, 0x9112,
                0x9120, 0x9122, 0x9161, 0x9162, 0x9163, 0x9164, 0x9203, 0x9204, 0x9205, 0x9206,
                0x9207, 0x9208, 0x9209, 0x920B, 0x920D, 0x9210, 0x9211, 0x9212, 0x9220, 0x9222,
                0x9261, 0x9262, 0x9263, 0x9264, 0x9330, 0x9331, 0x9403, 0x9405, 0x9408, 0x940B,
                0x9420, 0xA001, 0xA002, 0xA003,
            ],
        }
    }

    /// The baud rates of the device's main port as its manual lists them, ascending (the IR's
    /// `link`; empty: none listed).
    pub fn baud_rates(self) -> &'static [u32] {
        match self {
            Device::Gx5_45 => &[9600, 19200, 115200, 230400, 460800, 921600],
            Device::Cv7Ins => &[115200, 230400, 460800, 921600, 3000000],
        }
    }

    /// The names the device answers to in the wrong-model check: its title and its identity
    /// model name (the spec's `simulation.identity`), upper case without spaces and punctuation.
    pub fn model_names(self) -> &'static [&'static str] {
        match self {
            Device::Gx5_45 => &["3DMGX545"],
            Device::Cv7Ins => &["3DMCV7GNSSINS"],
        }
    }

    /// The default baud rate of the device's main port (`None`: its manual states none).
    pub fn default_baud(self) -> Option<u32> {
        match self {
            Device::Gx5_45 => Some(115200),
            Device::Cv7Ins => None,
        }
    }

    /// True when the device's manual documents the command or data quantity (set, descriptor);
    /// the sessions refuse a command for which this is false, before sending it.
    pub fn supports(self, set: u8, descriptor: u8) -> bool {
        let key = (u16::from(set) << 8) | u16::from(descriptor);
        self.commands().binary_search(&key).is_ok() || self.data().binary_search(&key).is_ok()
    }

    /// The device with identifier `id`.
    pub fn from_id(id: &str) -> Option<Self> {
        match id {
            "gx5_45" => Some(Device::Gx5_45),
            "cv7_ins" => Some(Device::Cv7Ins),
            _ => None,
        }
    }
}

/// Kind of a descriptor set, from the ranges of `set_kinds`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SetKind {
    /// Sets 0x01..=0x7F.
    Command,
    /// Sets 0x80..=0xFF.
    Data,
}

/// Kind of set `set`, if it is in a range of `set_kinds`.
pub fn set_kind(set: u8) -> Option<SetKind> {
    if (0x01..=0x7F).contains(&set) {
        return Some(SetKind::Command);
    }
    if (0x80..=0xFF).contains(&set) {
        return Some(SetKind::Data);
    }
    None
}

/// Whether the spec defines descriptor set `set`.
pub fn set_defined(set: u8) -> bool {
    matches!(
        set,
        0x01 | 0x0C
            | 0x0D
            | 0x0E
            | 0x13
            | 0x7F
            | 0x80
            | 0x81
            | 0x82
            | 0x91
            | 0x92
            | 0x93
            | 0x94
            | 0xA0
            | 0xFF
    )
}

/// A decoded field, by the group that defines it.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(u8)]
pub enum FieldValue {
    /// A field of set 0x01.
    Base(crate::base::SetField),
    /// A field of set 0x0C.
    Threedm(crate::threedm::SetField),
    /// A field of set 0x0D.
    Filter(crate::filter::SetField),
    /// A field of set 0x0E.
    Gnss(crate::gnss::SetField),
    /// A field of set 0x13.
    Aiding(crate::aiding::SetField),
    /// A field of set 0x7F.
    System(crate::system::SetField),
    /// A field of set 0x80.
    Sensor(crate::sensor::SetField),
    /// A field of set 0x81.
    GnssData(crate::gnss_data::SetField),
    /// A field of set 0x82.
    FilterData(crate::filter_data::SetField),
    /// A field of set 0x91.
    GnssReceiver1(crate::gnss_receiver_1::SetField),
    /// A field of set 0x92.
    GnssReceiver2(crate::gnss_receiver_2::SetField),
    /// A field of set 0x93.
    GnssCorrections(crate::gnss_corrections::SetField),
    /// A field of set 0x94.
    GnssExternal(crate::gnss_external::SetField),
    /// A field of set 0xA0.
    SystemData(crate::system_data::SetField),
    /// A field of set 0xFF.
    Shared(crate::shared::SetField),
    /// A reserved field.
    Reserved(crate::reserved::ReservedField),
}

impl FieldValue {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            FieldValue::Base(v) => v.descriptor(),
            FieldValue::Threedm(v) => v.descriptor(),
            FieldValue::Filter(v) => v.descriptor(),
            FieldValue::Gnss(v) => v.descriptor(),
            FieldValue::Aiding(v) => v.descriptor(),
            FieldValue::System(v) => v.descriptor(),
            FieldValue::Sensor(v) => v.descriptor(),
            FieldValue::GnssData(v) => v.descriptor(),
            FieldValue::FilterData(v) => v.descriptor(),
            FieldValue::GnssReceiver1(v) => v.descriptor(),
            FieldValue::GnssReceiver2(v) => v.descriptor(),
            FieldValue::GnssCorrections(v) => v.descriptor(),
            FieldValue::GnssExternal(v) => v.descriptor(),
            FieldValue::SystemData(v) => v.descriptor(),
            FieldValue::Shared(v) => v.descriptor(),
            FieldValue::Reserved(v) => v.descriptor(),
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            FieldValue::Base(v) => v.name(),
            FieldValue::Threedm(v) => v.name(),
            FieldValue::Filter(v) => v.name(),
            FieldValue::Gnss(v) => v.name(),
            FieldValue::Aiding(v) => v.name(),
            FieldValue::System(v) => v.name(),
            FieldValue::Sensor(v) => v.name(),
            FieldValue::GnssData(v) => v.name(),
            FieldValue::FilterData(v) => v.name(),
            FieldValue::GnssReceiver1(v) => v.name(),
            FieldValue::GnssReceiver2(v) => v.name(),
            FieldValue::GnssCorrections(v) => v.name(),
            FieldValue::GnssExternal(v) => v.name(),
            FieldValue::SystemData(v) => v.name(),
            FieldValue::Shared(v) => v.name(),
            FieldValue::Reserved(v) => v.name(),
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<Device> {
        match self {
            FieldValue::Base(v) => v.device(),
            FieldValue::Threedm(v) => v.device(),
            FieldValue::Filter(v) => v.device(),
            FieldValue::Gnss(v) => v.device(),
            FieldValue::Aiding(v) => v.device(),
            FieldValue::System(v) => v.device(),
            FieldValue::Sensor(v) => v.device(),
            FieldValue::GnssData(v) => v.device(),
            FieldValue::FilterData(v) => v.device(),
            FieldValue::GnssReceiver1(v) => v.device(),
            FieldValue::GnssReceiver2(v) => v.device(),
            FieldValue::GnssCorrections(v) => v.device(),
            FieldValue::GnssExternal(v) => v.device(),
            FieldValue::SystemData(v) => v.device(),
            FieldValue::Shared(v) => v.device(),
            FieldValue::Reserved(v) => v.device(),
        }
    }

    /// Encodes the field data (without the field header).
    pub fn encode_data(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        match self {
            FieldValue::Base(v) => v.encode_data(w),
            FieldValue::Threedm(v) => v.encode_data(w),
            FieldValue::Filter(v) => v.encode_data(w),
            FieldValue::Gnss(v) => v.encode_data(w),
            FieldValue::Aiding(v) => v.encode_data(w),
            FieldValue::System(v) => v.encode_data(w),
            FieldValue::Sensor(v) => v.encode_data(w),
            FieldValue::GnssData(v) => v.encode_data(w),
            FieldValue::FilterData(v) => v.encode_data(w),
            FieldValue::GnssReceiver1(v) => v.encode_data(w),
            FieldValue::GnssReceiver2(v) => v.encode_data(w),
            FieldValue::GnssCorrections(v) => v.encode_data(w),
            FieldValue::GnssExternal(v) => v.encode_data(w),
            FieldValue::SystemData(v) => v.encode_data(w),
            FieldValue::Shared(v) => v.encode_data(w),
            FieldValue::Reserved(v) => v.encode_data(w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn Write) -> fmt::Result {
        match self {
            FieldValue::Base(v) => v.write_values_json(w),
            FieldValue::Threedm(v) => v.write_values_json(w),
            FieldValue::Filter(v) => v.write_values_json(w),
            FieldValue::Gnss(v) => v.write_values_json(w),
            FieldValue::Aiding(v) => v.write_values_json(w),
            FieldValue::System(v) => v.write_values_json(w),
            FieldValue::Sensor(v) => v.write_values_json(w),
            FieldValue::GnssData(v) => v.write_values_json(w),
            FieldValue::FilterData(v) => v.write_values_json(w),
            FieldValue::GnssReceiver1(v) => v.write_values_json(w),
            FieldValue::GnssReceiver2(v) => v.write_values_json(w),
            FieldValue::GnssCorrections(v) => v.write_values_json(w),
            FieldValue::GnssExternal(v) => v.write_values_json(w),
            FieldValue::SystemData(v) => v.write_values_json(w),
            FieldValue::Shared(v) => v.write_values_json(w),
            FieldValue::Reserved(v) => v.write_values_json(w),
        }
    }

    /// Writes the canonical JSON of the field: descriptor, name, device (if the field has
    /// per-device layouts) and values.
    pub fn write_json(&self, w: &mut dyn Write) -> fmt::Result {
        w.write_char('{')?;
        write!(w, "\"descriptor\":{},\"name\":", self.descriptor())?;
        json::write_str(w, self.name())?;
        if let Some(device) = self.device() {
            w.write_str(",\"device\":")?;
            json::write_str(w, device.id())?;
        }
        w.write_str(",\"values\":")?;
        self.write_values_json(w)?;
        w.write_char('}')
    }

    /// Reads a decoded field back from JSON (dispatch as in [`decode_field`]).
    #[cfg(feature = "std")]
    pub fn from_json(
        set: u8,
        descriptor: u8,
        device: Option<Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        let found = match set {
            #[cfg(any(feature = "set-base", not(feature = "select-sets")))]
            0x01 => crate::base::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Base)),
            #[cfg(any(feature = "set-threedm", not(feature = "select-sets")))]
            0x0C => crate::threedm::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Threedm)),
            #[cfg(any(feature = "set-filter", not(feature = "select-sets")))]
            0x0D => crate::filter::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Filter)),
            #[cfg(any(feature = "set-gnss", not(feature = "select-sets")))]
            0x0E => crate::gnss::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Gnss)),
            #[cfg(any(feature = "set-aiding", not(feature = "select-sets")))]
            0x13 => crate::aiding::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Aiding)),
            #[cfg(any(feature = "set-system", not(feature = "select-sets")))]
            0x7F => crate::system::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::System)),
            #[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
            0x80 => crate::sensor::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Sensor)),
            #[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
            0x81 => crate::gnss_data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssData)),
            #[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
            0x82 => crate::filter_data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::FilterData)),
            #[cfg(any(feature = "set-gnss-receiver-1", not(feature = "select-sets")))]
            0x91 => crate::gnss_receiver_1::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssReceiver1)),
            #[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
            0x92 => crate::gnss_receiver_2::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssReceiver2)),
            #[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
            0x93 => crate::gnss_corrections::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssCorrections)),
            #[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
            0x94 => crate::gnss_external::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssExternal)),
            #[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
            0xA0 => crate::system_data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::SystemData)),
            #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
            0xFF => crate::shared::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Shared)),
            _ => None,
        };
        if let Some(result) = found {
            return result;
        }
        let kind = set_kind(set);
        if let Some(result) =
            crate::reserved::ReservedField::from_json(kind, descriptor, device, values)
        {
            return result.map(FieldValue::Reserved);
        }
        #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
        if kind == Some(SetKind::Data) {
            if let Some(result) = crate::shared::SetField::from_json(descriptor, device, values) {
                return result.map(FieldValue::Shared);
            }
        }
        Err(crate::json_read::JsonError::new(std::format!(
            "descriptor {descriptor} is not defined in set {set}; write the field raw, with \"data\""
        ))
        .at("descriptor"))
    }
}

/// Decodes the data of field `descriptor` in a packet of set `set`: the set's own field, else a
/// reserved field of the set's kind, else (in a data set) a field of the shared data set. With
/// `device`, fields that have per-device layouts use that device's layout.
///
/// With the cargo features `set-*` (Cargo.toml), only the selected sets' fields decode (the
/// others as an unknown set's: reserved fields only), and only their decoders are linked.
#[inline]
pub fn decode_field(
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> Result<FieldValue, DecodeError> {
    // The set's own fields and the shared data fields it does not define (the search order as
    // the generator resolves it): two table loads, straight to the field's decoder, which builds
    // the FieldValue in the caller's slot. Reserved fields and unknown descriptors go on.
    if let Some(decoders) = SET_DECODERS[usize::from(set)] {
        if let Some(decode) = decoders[usize::from(descriptor)] {
            return decode(data, device);
        }
    }
    decode_other_field(set, descriptor, data, device)
}

/// The decoder of one field (in `decoders`).
type Decoder = fn(&[u8], Option<Device>) -> Result<FieldValue, DecodeError>;

/// Decoders of a set's fields (its own and shared ones), by descriptor (`None`: look further).
type DescriptorDecoders = [Option<Decoder>; 256];

/// The decoder tables of every set that has any, by set (`None`: look further).
static SET_DECODERS: [Option<&DescriptorDecoders>; 256] = {
    // Only the sets of the dispatch (the cargo features `set-*`).
    #[allow(unused_mut)]
    let mut t: [Option<&DescriptorDecoders>; 256] = [None; 256];
    #[cfg(any(feature = "set-base", not(feature = "select-sets")))]
    {
        t[0x01] = Some(&BASE_DECODERS);
    }
    #[cfg(any(feature = "set-threedm", not(feature = "select-sets")))]
    {
        t[0x0C] = Some(&THREEDM_DECODERS);
    }
    #[cfg(any(feature = "set-filter", not(feature = "select-sets")))]
    {
        t[0x0D] = Some(&FILTER_DECODERS);
    }
    #[cfg(any(feature = "set-gnss", not(feature = "select-sets")))]
    {
        t[0x0E] = Some(&GNSS_DECODERS);
    }
    #[cfg(any(feature = "set-aiding", not(feature = "select-sets")))]
    {
        t[0x13] = Some(&AIDING_DECODERS);
    }
    #[cfg(any(feature = "set-system", not(feature = "select-sets")))]
    {
        t[0x7F] = Some(&SYSTEM_DECODERS);
    }
    #[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
    {
        t[0x80] = Some(&SENSOR_DECODERS);
    }
    #[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
    {
        t[0x81] = Some(&GNSS_DATA_DECODERS);
    }
    #[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
    {
        t[0x82] = Some(&FILTER_DATA_DECODERS);
    }
    #[cfg(any(feature = "set-gnss-receiver-1", not(feature = "select-sets")))]
    {
        t[0x91] = Some(&GNSS_RECEIVER_1_DECODERS);
    }
    #[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
    {
        t[0x92] = Some(&GNSS_RECEIVER_2_DECODERS);
    }
    #[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
    {
        t[0x93] = Some(&GNSS_CORRECTIONS_DECODERS);
    }
    #[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
    {
        t[0x94] = Some(&GNSS_EXTERNAL_DECODERS);
    }
    #[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
    {
        t[0xA0] = Some(&SYSTEM_DATA_DECODERS);
    }
    #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
    {
        t[0xFF] = Some(&SHARED_DECODERS);
    }
    t
};

/// Decoders of the fields of set 0x01 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-base", not(feature = "select-sets")))]
static BASE_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::base_ping);
    t[0x02] = Some(decoders::base_set_to_idle);
    t[0x03] = Some(decoders::base_get_device_info);
    t[0x04] = Some(decoders::base_get_device_descriptors);
    t[0x05] = Some(decoders::base_built_in_test);
    t[0x06] = Some(decoders::base_resume);
    t[0x07] = Some(decoders::base_get_extended_descriptors);
    t[0x08] = Some(decoders::base_continuous_bit);
    t[0x09] = Some(decoders::base_comm_port_speed);
    t[0x72] = Some(decoders::base_gps_time_update);
    t[0x7E] = Some(decoders::base_device_reset);
    t[0x81] = Some(decoders::base_device_info);
    t[0x82] = Some(decoders::base_device_descriptors);
    t[0x83] = Some(decoders::base_built_in_test_result);
    t[0x84] = Some(decoders::base_gps_week);
    t[0x85] = Some(decoders::base_gps_seconds);
    t[0x86] = Some(decoders::base_extended_descriptors);
    t[0x88] = Some(decoders::base_continuous_bit_result);
    t[0x89] = Some(decoders::base_comm_port_speed_response);
    t
};

/// Decoders of the fields of set 0x0C (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-threedm", not(feature = "select-sets")))]
static THREEDM_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::threedm_poll_imu_data);
    t[0x02] = Some(decoders::threedm_poll_gnss_data);
    t[0x03] = Some(decoders::threedm_poll_filter_data);
    t[0x04] = Some(decoders::threedm_poll_nmea_data);
    t[0x06] = Some(decoders::threedm_get_imu_base_rate);
    t[0x07] = Some(decoders::threedm_get_gnss_base_rate);
    t[0x08] = Some(decoders::threedm_imu_message_format);
    t[0x09] = Some(decoders::threedm_gnss_message_format);
    t[0x0A] = Some(decoders::threedm_filter_message_format);
    t[0x0B] = Some(decoders::threedm_get_filter_base_rate);
    t[0x0C] = Some(decoders::threedm_nmea_message_format);
    t[0x0D] = Some(decoders::threedm_poll_data);
    t[0x0E] = Some(decoders::threedm_get_base_rate);
    t[0x0F] = Some(decoders::threedm_message_format);
    t[0x10] = Some(decoders::threedm_factory_streaming);
    t[0x11] = Some(decoders::threedm_data_stream_control);
    t[0x20] = Some(decoders::threedm_raw_rtcm_message);
    t[0x21] = Some(decoders::threedm_gnss_constellation_settings);
    t[0x22] = Some(decoders::threedm_gnss_sbas_settings);
    t[0x23] = Some(decoders::threedm_gnss_assisted_fix_control);
    t[0x24] = Some(decoders::threedm_gnss_assist_time_update);
    t[0x28] = Some(decoders::threedm_pps_source);
    t[0x2A] = Some(decoders::threedm_get_supported_events);
    t[0x2B] = Some(decoders::threedm_event_control);
    t[0x2C] = Some(decoders::threedm_get_event_trigger_status);
    t[0x2D] = Some(decoders::threedm_get_event_action_status);
    t[0x2E] = Some(decoders::threedm_event_trigger_config);
    t[0x2F] = Some(decoders::threedm_event_action_config);
    t[0x30] = Some(decoders::threedm_device_startup_settings);
    t[0x31] = Some(decoders::threedm_sensor_to_vehicle_euler);
    t[0x32] = Some(decoders::threedm_sensor_to_vehicle_quaternion);
    t[0x33] = Some(decoders::threedm_sensor_to_vehicle_dcm);
    t[0x37] = Some(decoders::threedm_accel_bias);
    t[0x38] = Some(decoders::threedm_gyro_bias);
    t[0x39] = Some(decoders::threedm_capture_gyro_bias);
    t[0x3A] = Some(decoders::threedm_mag_hard_iron_offset);
    t[0x3B] = Some(decoders::threedm_mag_soft_iron_matrix);
    t[0x3E] = Some(decoders::threedm_coning_sculling_enable);
    t[0x40] = Some(decoders::threedm_uart_baudrate);
    t[0x41] = Some(decoders::threedm_gpio_config);
    t[0x42] = Some(decoders::threedm_gpio_state);
    t[0x43] = Some(decoders::threedm_odometer_config);
    t[0x50] = Some(decoders::threedm_advanced_lowpass_filter);
    t[0x51] = Some(decoders::threedm_complementary_filter);
    t[0x52] = Some(decoders::threedm_sensor_range);
    t[0x53] = Some(decoders::threedm_get_calibrated_sensor_ranges);
    t[0x54] = Some(decoders::threedm_lowpass_filter);
    t[0x64] = Some(decoders::threedm_device_status);
    t[0x80] = Some(decoders::threedm_imu_message_format_response);
    t[0x81] = Some(decoders::threedm_gnss_message_format_response);
    t[0x82] = Some(decoders::threedm_filter_message_format_response);
    t[0x83] = Some(decoders::threedm_imu_base_rate);
    t[0x84] = Some(decoders::threedm_gnss_base_rate);
    t[0x85] = Some(decoders::threedm_data_stream_control_response);
    t[0x87] = Some(decoders::threedm_uart_baudrate_response);
    t[0x8A] = Some(decoders::threedm_filter_base_rate);
    t[0x8B] = Some(decoders::threedm_advanced_lowpass_filter_response);
    t[0x8C] = Some(decoders::threedm_nmea_message_format_response);
    t[0x8E] = Some(decoders::threedm_base_rate);
    t[0x8F] = Some(decoders::threedm_message_format_response);
    t[0x90] = Some(decoders::threedm_device_status_response);
    t[0x97] = Some(decoders::threedm_complementary_filter_response);
    t[0x9A] = Some(decoders::threedm_accel_bias_response);
    t[0x9B] = Some(decoders::threedm_gyro_bias_response);
    t[0x9C] = Some(decoders::threedm_mag_hard_iron_offset_response);
    t[0x9D] = Some(decoders::threedm_mag_soft_iron_matrix_response);
    t[0x9E] = Some(decoders::threedm_coning_sculling_enable_response);
    t[0xA0] = Some(decoders::threedm_gnss_constellation_settings_response);
    t[0xA1] = Some(decoders::threedm_gnss_sbas_settings_response);
    t[0xA2] = Some(decoders::threedm_gnss_assisted_fix_control_response);
    t[0xA3] = Some(decoders::threedm_gnss_assist_time_update_response);
    t[0xA8] = Some(decoders::threedm_pps_source_response);
    t[0xB1] = Some(decoders::threedm_sensor_to_vehicle_euler_response);
    t[0xB2] = Some(decoders::threedm_sensor_to_vehicle_quaternion_response);
    t[0xB3] = Some(decoders::threedm_sensor_to_vehicle_dcm_response);
    t[0xB4] = Some(decoders::threedm_supported_events);
    t[0xB5] = Some(decoders::threedm_event_control_response);
    t[0xB6] = Some(decoders::threedm_event_trigger_status);
    t[0xB7] = Some(decoders::threedm_event_action_status);
    t[0xB8] = Some(decoders::threedm_event_trigger_config_response);
    t[0xB9] = Some(decoders::threedm_event_action_config_response);
    t[0xC1] = Some(decoders::threedm_gpio_config_response);
    t[0xC2] = Some(decoders::threedm_gpio_state_response);
    t[0xC3] = Some(decoders::threedm_odometer_config_response);
    t[0xD2] = Some(decoders::threedm_sensor_range_response);
    t[0xD3] = Some(decoders::threedm_calibrated_sensor_ranges);
    t[0xD4] = Some(decoders::threedm_lowpass_filter_response);
    t
};

/// Decoders of the fields of set 0x0D (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-filter", not(feature = "select-sets")))]
static FILTER_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::filter_reset_filter);
    t[0x02] = Some(decoders::filter_set_initial_attitude);
    t[0x03] = Some(decoders::filter_set_initial_heading);
    t[0x05] = Some(decoders::filter_run_filter);
    t[0x10] = Some(decoders::filter_vehicle_dynamics_mode);
    t[0x11] = Some(decoders::filter_sensor_to_vehicle_transform);
    t[0x12] = Some(decoders::filter_sensor_to_vehicle_offset);
    t[0x13] = Some(decoders::filter_antenna_offset);
    t[0x14] = Some(decoders::filter_estimation_control);
    t[0x15] = Some(decoders::filter_gnss_source_control);
    t[0x16] = Some(decoders::filter_external_gnss_update);
    t[0x17] = Some(decoders::filter_external_heading_update);
    t[0x18] = Some(decoders::filter_heading_update_control);
    t[0x19] = Some(decoders::filter_auto_init_control);
    t[0x1A] = Some(decoders::filter_accel_noise);
    t[0x1B] = Some(decoders::filter_gyro_noise);
    t[0x1C] = Some(decoders::filter_accel_bias_model);
    t[0x1D] = Some(decoders::filter_gyro_bias_model);
    t[0x1E] = Some(decoders::filter_zupt_control);
    t[0x1F] = Some(decoders::filter_external_heading_update_with_time);
    t[0x20] = Some(decoders::filter_zero_angular_rate_update_control);
    t[0x21] = Some(decoders::filter_tare_orientation);
    t[0x22] = Some(decoders::filter_commanded_zupt);
    t[0x23] = Some(decoders::filter_commanded_zero_angular_rate_update);
    t[0x27] = Some(decoders::filter_mag_capture_auto_calibration);
    t[0x28] = Some(decoders::filter_gravity_noise_std_dev);
    t[0x29] = Some(decoders::filter_pressure_altitude_noise_std_dev);
    t[0x2B] = Some(decoders::filter_hard_iron_offset_noise);
    t[0x2C] = Some(decoders::filter_soft_iron_matrix_noise);
    t[0x42] = Some(decoders::filter_mag_noise_std_dev);
    t[0x43] = Some(decoders::filter_declination_source);
    t[0x44] = Some(decoders::filter_gravity_magnitude_adaptive_measurement);
    t[0x45] = Some(decoders::filter_mag_magnitude_adaptive_measurement);
    t[0x46] = Some(decoders::filter_mag_dip_angle_adaptive_measurement);
    t[0x47] = Some(decoders::filter_altitude_aiding_control);
    t[0x4B] = Some(decoders::filter_pitch_roll_aiding_control);
    t[0x4C] = Some(decoders::filter_inclination_source);
    t[0x4D] = Some(decoders::filter_magnetic_field_magnitude_source);
    t[0x50] = Some(decoders::filter_aiding_measurement_control);
    t[0x52] = Some(decoders::filter_initialization_configuration);
    t[0x53] = Some(decoders::filter_adaptive_filter_control);
    t[0x54] = Some(decoders::filter_multi_antenna_offset);
    t[0x55] = Some(decoders::filter_relative_position_configuration);
    t[0x56] = Some(decoders::filter_reference_point_lever_arm);
    t[0x61] = Some(decoders::filter_speed_lever_arm);
    t[0x63] = Some(decoders::filter_wheeled_vehicle_constraint_control);
    t[0x64] = Some(decoders::filter_gnss_antenna_calibration_control);
    t[0x80] = Some(decoders::filter_vehicle_dynamics_mode_response);
    t[0x81] = Some(decoders::filter_sensor_to_vehicle_transform_response);
    t[0x82] = Some(decoders::filter_sensor_to_vehicle_offset_response);
    t[0x83] = Some(decoders::filter_antenna_offset_response);
    t[0x84] = Some(decoders::filter_estimation_control_response);
    t[0x86] = Some(decoders::filter_gnss_source_control_response);
    t[0x87] = Some(decoders::filter_heading_update_control_response);
    t[0x88] = Some(decoders::filter_auto_init_control_response);
    t[0x89] = Some(decoders::filter_accel_noise_response);
    t[0x8A] = Some(decoders::filter_gyro_noise_response);
    t[0x8B] = Some(decoders::filter_accel_bias_model_response);
    t[0x8C] = Some(decoders::filter_gyro_bias_model_response);
    t[0x8D] = Some(decoders::filter_zupt_control_response);
    t[0x8E] = Some(decoders::filter_zero_angular_rate_update_control_response);
    t[0x93] = Some(decoders::filter_gravity_noise_std_dev_response);
    t[0x94] = Some(decoders::filter_pressure_altitude_noise_std_dev_response);
    t[0x96] = Some(decoders::filter_hard_iron_offset_noise_response);
    t[0x97] = Some(decoders::filter_soft_iron_matrix_noise_response);
    t[0xB1] = Some(decoders::filter_mag_noise_std_dev_response);
    t[0xB2] = Some(decoders::filter_declination_source_response);
    t[0xB3] = Some(decoders::filter_gravity_magnitude_adaptive_measurement_response);
    t[0xB4] = Some(decoders::filter_mag_magnitude_adaptive_measurement_response);
    t[0xB5] = Some(decoders::filter_mag_dip_angle_adaptive_measurement_response);
    t[0xB7] = Some(decoders::filter_altitude_aiding_control_response);
    t[0xBB] = Some(decoders::filter_pitch_roll_aiding_control_response);
    t[0xBC] = Some(decoders::filter_inclination_source_response);
    t[0xBD] = Some(decoders::filter_magnetic_field_magnitude_source_response);
    t[0xD0] = Some(decoders::filter_aiding_measurement_control_response);
    t[0xD2] = Some(decoders::filter_initialization_configuration_response);
    t[0xD3] = Some(decoders::filter_adaptive_filter_control_response);
    t[0xD4] = Some(decoders::filter_multi_antenna_offset_response);
    t[0xD5] = Some(decoders::filter_relative_position_configuration_response);
    t[0xD6] = Some(decoders::filter_reference_point_lever_arm_response);
    t[0xE1] = Some(decoders::filter_speed_lever_arm_response);
    t[0xE3] = Some(decoders::filter_wheeled_vehicle_constraint_control_response);
    t[0xE4] = Some(decoders::filter_gnss_antenna_calibration_control_response);
    t
};

/// Decoders of the fields of set 0x0E (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-gnss", not(feature = "select-sets")))]
static GNSS_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::gnss_receiver_info);
    t[0x02] = Some(decoders::gnss_signal_configuration);
    t[0x20] = Some(decoders::gnss_spartn_configuration);
    t[0x81] = Some(decoders::gnss_receiver_info_response);
    t[0x82] = Some(decoders::gnss_signal_configuration_response);
    t[0xA0] = Some(decoders::gnss_spartn_configuration_response);
    t
};

/// Decoders of the fields of set 0x13 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-aiding", not(feature = "select-sets")))]
static AIDING_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::aiding_frame_config);
    t[0x1F] = Some(decoders::aiding_echo_control);
    t[0x21] = Some(decoders::aiding_ecef_position);
    t[0x22] = Some(decoders::aiding_llh_position);
    t[0x23] = Some(decoders::aiding_height_above_ellipsoid);
    t[0x28] = Some(decoders::aiding_ecef_velocity);
    t[0x29] = Some(decoders::aiding_ned_velocity);
    t[0x2A] = Some(decoders::aiding_body_frame_velocity);
    t[0x31] = Some(decoders::aiding_true_heading);
    t[0x32] = Some(decoders::aiding_magnetic_field);
    t[0x33] = Some(decoders::aiding_pressure);
    t[0x81] = Some(decoders::aiding_frame_config_response);
    t[0x9F] = Some(decoders::aiding_echo_control_response);
    t
};

/// Decoders of the fields of set 0x7F (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-system", not(feature = "select-sets")))]
static SYSTEM_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x10] = Some(decoders::system_communication_mode);
    t[0x90] = Some(decoders::system_communication_mode_response);
    t
};

/// Decoders of the fields of set 0x80 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
static SENSOR_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x04] = Some(decoders::sensor_scaled_accel);
    t[0x05] = Some(decoders::sensor_scaled_gyro);
    t[0x06] = Some(decoders::sensor_scaled_mag);
    t[0x07] = Some(decoders::sensor_delta_theta);
    t[0x08] = Some(decoders::sensor_delta_velocity);
    t[0x09] = Some(decoders::sensor_cf_orientation_matrix);
    t[0x0A] = Some(decoders::sensor_cf_quaternion);
    t[0x0C] = Some(decoders::sensor_cf_euler_angles);
    t[0x10] = Some(decoders::sensor_cf_stabilized_north);
    t[0x11] = Some(decoders::sensor_cf_stabilized_up);
    t[0x12] = Some(decoders::sensor_gps_timestamp);
    t[0x14] = Some(decoders::sensor_temperature_statistics);
    t[0x17] = Some(decoders::sensor_scaled_pressure);
    t[0x18] = Some(decoders::sensor_overrange_status);
    t[0x40] = Some(decoders::sensor_odometer_data);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0x81 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
static GNSS_DATA_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x03] = Some(decoders::gnss_data_llh_position);
    t[0x04] = Some(decoders::gnss_data_ecef_position);
    t[0x05] = Some(decoders::gnss_data_ned_velocity);
    t[0x06] = Some(decoders::gnss_data_ecef_velocity);
    t[0x07] = Some(decoders::gnss_data_dop);
    t[0x08] = Some(decoders::gnss_data_utc_time);
    t[0x09] = Some(decoders::gnss_data_gps_time);
    t[0x0A] = Some(decoders::gnss_data_clock_info);
    t[0x0B] = Some(decoders::gnss_data_fix_info);
    t[0x0C] = Some(decoders::gnss_data_sv_info);
    t[0x0D] = Some(decoders::gnss_data_hardware_status);
    t[0x0E] = Some(decoders::gnss_data_dgnss_info);
    t[0x0F] = Some(decoders::gnss_data_dgnss_channel_status);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0x82 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
static FILTER_DATA_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::filter_data_llh_position);
    t[0x02] = Some(decoders::filter_data_ned_velocity);
    t[0x03] = Some(decoders::filter_data_attitude_quaternion);
    t[0x04] = Some(decoders::filter_data_attitude_dcm);
    t[0x05] = Some(decoders::filter_data_euler_angles);
    t[0x06] = Some(decoders::filter_data_gyro_bias);
    t[0x07] = Some(decoders::filter_data_accel_bias);
    t[0x08] = Some(decoders::filter_data_llh_position_uncertainty);
    t[0x09] = Some(decoders::filter_data_ned_velocity_uncertainty);
    t[0x0A] = Some(decoders::filter_data_euler_angles_uncertainty);
    t[0x0B] = Some(decoders::filter_data_gyro_bias_uncertainty);
    t[0x0C] = Some(decoders::filter_data_accel_bias_uncertainty);
    t[0x0D] = Some(decoders::filter_data_linear_accel);
    t[0x0E] = Some(decoders::filter_data_comp_angular_rate);
    t[0x0F] = Some(decoders::filter_data_wgs84_gravity_magnitude);
    t[0x10] = Some(decoders::filter_data_filter_status);
    t[0x11] = Some(decoders::filter_data_gps_timestamp);
    t[0x12] = Some(decoders::filter_data_quaternion_attitude_uncertainty);
    t[0x13] = Some(decoders::filter_data_gravity_vector);
    t[0x14] = Some(decoders::filter_data_heading_update_state);
    t[0x15] = Some(decoders::filter_data_magnetic_model);
    t[0x16] = Some(decoders::filter_data_gyro_scale_factor);
    t[0x17] = Some(decoders::filter_data_accel_scale_factor);
    t[0x18] = Some(decoders::filter_data_gyro_scale_factor_uncertainty);
    t[0x19] = Some(decoders::filter_data_accel_scale_factor_uncertainty);
    t[0x1C] = Some(decoders::filter_data_compensated_accel);
    t[0x20] = Some(decoders::filter_data_standard_atmosphere);
    t[0x21] = Some(decoders::filter_data_pressure_altitude);
    t[0x25] = Some(decoders::filter_data_mag_auto_hard_iron_offset);
    t[0x26] = Some(decoders::filter_data_mag_auto_soft_iron_matrix);
    t[0x28] = Some(decoders::filter_data_mag_auto_hard_iron_offset_uncertainty);
    t[0x29] = Some(decoders::filter_data_mag_auto_soft_iron_matrix_uncertainty);
    t[0x30] = Some(decoders::filter_data_gnss_antenna_offset_correction);
    t[0x31] = Some(decoders::filter_data_gnss_antenna_offset_correction_uncertainty);
    t[0x34] = Some(decoders::filter_data_multi_antenna_offset_correction);
    t[0x35] = Some(decoders::filter_data_multi_antenna_offset_correction_uncertainty);
    t[0x36] = Some(decoders::filter_data_ecef_position_uncertainty);
    t[0x37] = Some(decoders::filter_data_ecef_velocity_uncertainty);
    t[0x40] = Some(decoders::filter_data_ecef_position);
    t[0x41] = Some(decoders::filter_data_ecef_velocity);
    t[0x42] = Some(decoders::filter_data_ned_relative_position);
    t[0x43] = Some(decoders::filter_data_gnss_position_aiding_status);
    t[0x46] = Some(decoders::filter_data_aiding_measurement_summary);
    t[0x47] = Some(decoders::filter_data_odometer_scale_factor_error);
    t[0x48] = Some(decoders::filter_data_odometer_scale_factor_error_uncertainty);
    t[0x49] = Some(decoders::filter_data_gnss_dual_antenna_status);
    t[0x50] = Some(decoders::filter_data_aiding_frame_config_error);
    t[0x51] = Some(decoders::filter_data_aiding_frame_config_error_uncertainty);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0x91 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-gnss-receiver-1", not(feature = "select-sets")))]
static GNSS_RECEIVER_1_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x03] = Some(decoders::gnss_receiver_1_llh_position);
    t[0x04] = Some(decoders::gnss_receiver_1_ecef_position);
    t[0x05] = Some(decoders::gnss_receiver_1_ned_velocity);
    t[0x06] = Some(decoders::gnss_receiver_1_ecef_velocity);
    t[0x07] = Some(decoders::gnss_receiver_1_dop);
    t[0x08] = Some(decoders::gnss_receiver_1_utc_time);
    t[0x09] = Some(decoders::gnss_receiver_1_gps_time);
    t[0x0B] = Some(decoders::gnss_receiver_1_fix_info);
    t[0x0D] = Some(decoders::gnss_receiver_1_hardware_status);
    t[0x10] = Some(decoders::gnss_receiver_1_clock_info_2);
    t[0x11] = Some(decoders::gnss_receiver_1_gps_leap_seconds);
    t[0x12] = Some(decoders::gnss_receiver_1_sbas_info);
    t[0x20] = Some(decoders::gnss_receiver_1_satellite_status);
    t[0x22] = Some(decoders::gnss_receiver_1_raw);
    t[0x61] = Some(decoders::gnss_receiver_1_gps_ephemeris);
    t[0x62] = Some(decoders::gnss_receiver_1_glonass_ephemeris);
    t[0x63] = Some(decoders::gnss_receiver_1_galileo_ephemeris);
    t[0x64] = Some(decoders::gnss_receiver_1_beidou_ephemeris);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0x92 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
static GNSS_RECEIVER_2_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x03] = Some(decoders::gnss_receiver_2_llh_position);
    t[0x04] = Some(decoders::gnss_receiver_2_ecef_position);
    t[0x05] = Some(decoders::gnss_receiver_2_ned_velocity);
    t[0x06] = Some(decoders::gnss_receiver_2_ecef_velocity);
    t[0x07] = Some(decoders::gnss_receiver_2_dop);
    t[0x08] = Some(decoders::gnss_receiver_2_utc_time);
    t[0x09] = Some(decoders::gnss_receiver_2_gps_time);
    t[0x0B] = Some(decoders::gnss_receiver_2_fix_info);
    t[0x0D] = Some(decoders::gnss_receiver_2_hardware_status);
    t[0x10] = Some(decoders::gnss_receiver_2_clock_info_2);
    t[0x11] = Some(decoders::gnss_receiver_2_gps_leap_seconds);
    t[0x12] = Some(decoders::gnss_receiver_2_sbas_info);
    t[0x20] = Some(decoders::gnss_receiver_2_satellite_status);
    t[0x22] = Some(decoders::gnss_receiver_2_raw);
    t[0x61] = Some(decoders::gnss_receiver_2_gps_ephemeris);
    t[0x62] = Some(decoders::gnss_receiver_2_glonass_ephemeris);
    t[0x63] = Some(decoders::gnss_receiver_2_galileo_ephemeris);
    t[0x64] = Some(decoders::gnss_receiver_2_beidou_ephemeris);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0x93 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
static GNSS_CORRECTIONS_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x30] = Some(decoders::gnss_corrections_base_station_info);
    t[0x31] = Some(decoders::gnss_corrections_rtk_corrections_status);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0x94 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
static GNSS_EXTERNAL_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x03] = Some(decoders::gnss_external_llh_position);
    t[0x05] = Some(decoders::gnss_external_ned_velocity);
    t[0x08] = Some(decoders::gnss_external_utc_time);
    t[0x0B] = Some(decoders::gnss_external_fix_info);
    t[0x20] = Some(decoders::gnss_external_satellite_status);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0xA0 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
static SYSTEM_DATA_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::system_data_built_in_test);
    t[0x02] = Some(decoders::system_data_time_sync_status);
    t[0x03] = Some(decoders::system_data_gpio_state);
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// Decoders of the fields of set 0xFF (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
static SHARED_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0xD0] = Some(decoders::shared_event_source);
    t[0xD3] = Some(decoders::shared_gps_timestamp);
    t[0xD4] = Some(decoders::shared_delta_time);
    t[0xD5] = Some(decoders::shared_reference_timestamp);
    t[0xD6] = Some(decoders::shared_reference_time_delta);
    t[0xD7] = Some(decoders::shared_external_timestamp);
    t[0xD8] = Some(decoders::shared_external_time_delta);
    t
};

/// [`decode_field`] for a descriptor that is not one of the set's own fields. Out of line, so
/// that `decode_field` itself is only the table lookup.
#[inline(never)]
fn decode_other_field(
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> Result<FieldValue, DecodeError> {
    // Not every protocol has reserved or shared fields to look at.
    let _ = (descriptor, data, device);
    let kind = set_kind(set);
    if let Some(result) = crate::reserved::ReservedField::decode(kind, descriptor, data) {
        return result.map(FieldValue::Reserved);
    }
    #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
    if kind == Some(SetKind::Data) {
        if let Some(result) = crate::shared::SetField::decode(descriptor, data, device) {
            return result.map(FieldValue::Shared);
        }
    }
    Err(DecodeError::new(if set_in_dispatch(set) {
        DecodeErrorKind::UnknownDescriptor
    } else {
        DecodeErrorKind::UnknownSet
    }))
}

/// Whether set `set` is in the dispatch: defined by the spec and selected by the cargo features
/// `set-*` (every defined set when none of them is on).
fn set_in_dispatch(set: u8) -> bool {
    match set {
        #[cfg(any(feature = "set-base", not(feature = "select-sets")))]
        0x01 => true,
        #[cfg(any(feature = "set-threedm", not(feature = "select-sets")))]
        0x0C => true,
        #[cfg(any(feature = "set-filter", not(feature = "select-sets")))]
        0x0D => true,
        #[cfg(any(feature = "set-gnss", not(feature = "select-sets")))]
        0x0E => true,
        #[cfg(any(feature = "set-aiding", not(feature = "select-sets")))]
        0x13 => true,
        #[cfg(any(feature = "set-system", not(feature = "select-sets")))]
        0x7F => true,
        #[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
        0x80 => true,
        #[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
        0x81 => true,
        #[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
        0x82 => true,
        #[cfg(any(feature = "set-gnss-receiver-1", not(feature = "select-sets")))]
        0x91 => true,
        #[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
        0x92 => true,
        #[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
        0x93 => true,
        #[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
        0x94 => true,
        #[cfg(any(feature = "set-system-data", not(feature = "select-sets")))]
        0xA0 => true,
        #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
        0xFF => true,
        _ => false,
    }
}

/// One decoder per field of every set, for [`decode_field`] (through the tables above). Not
/// inlined, so that each keeps its own stack frame, as large as its own layout only. With a
/// selection of sets (the cargo features `set-*`) the others' decoders are not used.
mod decoders {
    #![cfg_attr(feature = "select-sets", allow(dead_code))]

    use super::{DecodeError, Device, FieldValue};
    use crate::wire::{Layout, Reader};

    /// Decodes `data` as layout `L` and wraps it into a FieldValue. A fixed layout over exactly
    /// its size is read straight into the caller's slot; anything else (a wrong length, an
    /// invalid value) goes to the checked decode, out of line, so that the straight path needs
    /// no room for an error.
    #[inline(always)]
    fn decode_layout<L: Layout, W: FnOnce(L) -> FieldValue>(
        data: &[u8],
        wrap: W,
    ) -> Result<FieldValue, DecodeError> {
        match L::FIXED_SIZE {
            Some(size) => {
                if size == data.len() {
                    if let Ok(value) = L::decode(&mut Reader::new(data)) {
                        return Ok(wrap(value));
                    }
                }
                decode_layout_checked(data, wrap)
            }
            None => L::decode_data(data).map(wrap),
        }
    }

    /// The checked decode of [`decode_layout`] (the same value or error as
    /// [`Layout::decode_data`]).
    #[cold]
    #[inline(never)]
    fn decode_layout_checked<L: Layout, W: FnOnce(L) -> FieldValue>(
        data: &[u8],
        wrap: W,
    ) -> Result<FieldValue, DecodeError> {
        L::decode_data(data).map(wrap)
    }

    #[inline(never)]
    pub(super) fn base_ping(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::Ping| {
            FieldValue::Base(crate::base::SetField::Ping(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_set_to_idle(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::SetToIdle| {
            FieldValue::Base(crate::base::SetField::SetToIdle(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_device_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetDeviceInfo| {
            FieldValue::Base(crate::base::SetField::GetDeviceInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceInfo| {
            FieldValue::Base(crate::base::SetField::DeviceInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_device_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetDeviceDescriptors| {
            FieldValue::Base(crate::base::SetField::GetDeviceDescriptors(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceDescriptors| {
            FieldValue::Base(crate::base::SetField::DeviceDescriptors(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_built_in_test(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::BuiltInTest| {
            FieldValue::Base(crate::base::SetField::BuiltInTest(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_built_in_test_result(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::base::BuiltInTestResult::decode_data(data, device)
            .map(|v| FieldValue::Base(crate::base::SetField::BuiltInTestResult(v)))
    }

    #[inline(never)]
    pub(super) fn base_resume(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::Resume| {
            FieldValue::Base(crate::base::SetField::Resume(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_extended_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetExtendedDescriptors| {
            FieldValue::Base(crate::base::SetField::GetExtendedDescriptors(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_extended_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::ExtendedDescriptors| {
            FieldValue::Base(crate::base::SetField::ExtendedDescriptors(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_continuous_bit(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::ContinuousBit| {
            FieldValue::Base(crate::base::SetField::ContinuousBit(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_continuous_bit_result(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::ContinuousBitResult| {
            FieldValue::Base(crate::base::SetField::ContinuousBitResult(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_comm_port_speed(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::CommPortSpeed| {
            FieldValue::Base(crate::base::SetField::CommPortSpeed(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_comm_port_speed_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::CommPortSpeedResponse| {
            FieldValue::Base(crate::base::SetField::CommPortSpeedResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_gps_time_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::base::GpsTimeUpdate::decode_data(data, device)
            .map(|v| FieldValue::Base(crate::base::SetField::GpsTimeUpdate(v)))
    }

    #[inline(never)]
    pub(super) fn base_gps_week(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GpsWeek| {
            FieldValue::Base(crate::base::SetField::GpsWeek(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_gps_seconds(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GpsSeconds| {
            FieldValue::Base(crate::base::SetField::GpsSeconds(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_reset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceReset| {
            FieldValue::Base(crate::base::SetField::DeviceReset(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventControl| {
            FieldValue::Threedm(crate::threedm::SetField::EventControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventControlResponse| {
            FieldValue::Threedm(crate::threedm::SetField::EventControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_event_trigger_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetEventTriggerStatus| {
            FieldValue::Threedm(crate::threedm::SetField::GetEventTriggerStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_trigger_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventTriggerStatus| {
            FieldValue::Threedm(crate::threedm::SetField::EventTriggerStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_event_action_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetEventActionStatus| {
            FieldValue::Threedm(crate::threedm::SetField::GetEventActionStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_action_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventActionStatus| {
            FieldValue::Threedm(crate::threedm::SetField::EventActionStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_trigger_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventTriggerConfig| {
            FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_trigger_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventTriggerConfigResponse| {
            FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfigResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_action_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventActionConfig| {
            FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_event_action_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::EventActionConfigResponse| {
            FieldValue::Threedm(crate::threedm::SetField::EventActionConfigResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_device_startup_settings(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::DeviceStartupSettings::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_euler(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SensorToVehicleEuler| {
            FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_euler_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SensorToVehicleEulerResponse| {
            FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEulerResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_quaternion(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SensorToVehicleQuaternion| {
            FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_quaternion_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::threedm::SensorToVehicleQuaternionResponse| {
                FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternionResponse(
                    v,
                ))
            },
        )
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_dcm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SensorToVehicleDcm| {
            FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_dcm_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SensorToVehicleDcmResponse| {
            FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcmResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_accel_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::AccelBias::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::AccelBias(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_accel_bias_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::AccelBiasResponse| {
            FieldValue::Threedm(crate::threedm::SetField::AccelBiasResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gyro_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::GyroBias::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GyroBias(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gyro_bias_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GyroBiasResponse| {
            FieldValue::Threedm(crate::threedm::SetField::GyroBiasResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_capture_gyro_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::CaptureGyroBias| {
            FieldValue::Threedm(crate::threedm::SetField::CaptureGyroBias(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_mag_hard_iron_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::MagHardIronOffset::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_mag_hard_iron_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::MagHardIronOffsetResponse| {
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffsetResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_mag_soft_iron_matrix(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::MagSoftIronMatrix::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_mag_soft_iron_matrix_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::MagSoftIronMatrixResponse| {
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrixResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_coning_sculling_enable(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::ConingScullingEnable| {
            FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_coning_sculling_enable_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::ConingScullingEnableResponse| {
            FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnableResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_uart_baudrate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::UartBaudrate| {
            FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_uart_baudrate_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::UartBaudrateResponse| {
            FieldValue::Threedm(crate::threedm::SetField::UartBaudrateResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GpioConfig| {
            FieldValue::Threedm(crate::threedm::SetField::GpioConfig(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GpioConfigResponse| {
            FieldValue::Threedm(crate::threedm::SetField::GpioConfigResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_state(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GpioState| {
            FieldValue::Threedm(crate::threedm::SetField::GpioState(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_state_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GpioStateResponse| {
            FieldValue::Threedm(crate::threedm::SetField::GpioStateResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_odometer_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::OdometerConfig| {
            FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_odometer_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::OdometerConfigResponse| {
            FieldValue::Threedm(crate::threedm::SetField::OdometerConfigResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_advanced_lowpass_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::AdvancedLowpassFilter| {
            FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_advanced_lowpass_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::AdvancedLowpassFilterResponse| {
            FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilterResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_complementary_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::ComplementaryFilter| {
            FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_complementary_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::ComplementaryFilterResponse| {
            FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilterResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SensorRange| {
            FieldValue::Threedm(crate::threedm::SetField::SensorRange(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SensorRangeResponse| {
            FieldValue::Threedm(crate::threedm::SetField::SensorRangeResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_calibrated_sensor_ranges(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetCalibratedSensorRanges| {
            FieldValue::Threedm(crate::threedm::SetField::GetCalibratedSensorRanges(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_calibrated_sensor_ranges(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::CalibratedSensorRanges| {
            FieldValue::Threedm(crate::threedm::SetField::CalibratedSensorRanges(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_lowpass_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::LowpassFilter| {
            FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_lowpass_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::LowpassFilterResponse| {
            FieldValue::Threedm(crate::threedm::SetField::LowpassFilterResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_poll_imu_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::PollImuData| {
            FieldValue::Threedm(crate::threedm::SetField::PollImuData(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_poll_gnss_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::PollGnssData| {
            FieldValue::Threedm(crate::threedm::SetField::PollGnssData(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_poll_filter_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::PollFilterData| {
            FieldValue::Threedm(crate::threedm::SetField::PollFilterData(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_poll_nmea_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::PollNmeaData| {
            FieldValue::Threedm(crate::threedm::SetField::PollNmeaData(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_poll_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::PollData| {
            FieldValue::Threedm(crate::threedm::SetField::PollData(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_imu_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetImuBaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::GetImuBaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_imu_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::ImuBaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::ImuBaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_gnss_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetGnssBaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::GetGnssBaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssBaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::GnssBaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_filter_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetFilterBaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::GetFilterBaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_filter_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::FilterBaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::FilterBaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetBaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::GetBaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::BaseRate| {
            FieldValue::Threedm(crate::threedm::SetField::BaseRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_imu_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::ImuMessageFormat| {
            FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_imu_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::ImuMessageFormatResponse| {
            FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormatResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssMessageFormat| {
            FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssMessageFormatResponse| {
            FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormatResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_filter_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::FilterMessageFormat| {
            FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_filter_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::FilterMessageFormatResponse| {
            FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormatResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_nmea_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::NmeaMessageFormat| {
            FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_nmea_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::NmeaMessageFormatResponse| {
            FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormatResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::MessageFormat| {
            FieldValue::Threedm(crate::threedm::SetField::MessageFormat(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::MessageFormatResponse| {
            FieldValue::Threedm(crate::threedm::SetField::MessageFormatResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_factory_streaming(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::FactoryStreaming| {
            FieldValue::Threedm(crate::threedm::SetField::FactoryStreaming(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_data_stream_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::DataStreamControl::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_data_stream_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::DataStreamControlResponse::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DataStreamControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_raw_rtcm_message(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::RawRtcmMessage| {
            FieldValue::Threedm(crate::threedm::SetField::RawRtcmMessage(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_constellation_settings(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssConstellationSettings| {
            FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_constellation_settings_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::threedm::GnssConstellationSettingsResponse| {
                FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettingsResponse(
                    v,
                ))
            },
        )
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_sbas_settings(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssSbasSettings| {
            FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_sbas_settings_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssSbasSettingsResponse| {
            FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettingsResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assisted_fix_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssAssistedFixControl| {
            FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assisted_fix_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssAssistedFixControlResponse| {
            FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assist_time_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssAssistTimeUpdate| {
            FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdate(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assist_time_update_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GnssAssistTimeUpdateResponse| {
            FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdateResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_pps_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::PpsSource| {
            FieldValue::Threedm(crate::threedm::SetField::PpsSource(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_pps_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::PpsSourceResponse| {
            FieldValue::Threedm(crate::threedm::SetField::PpsSourceResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_get_supported_events(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::GetSupportedEvents| {
            FieldValue::Threedm(crate::threedm::SetField::GetSupportedEvents(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_supported_events(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::SupportedEvents| {
            FieldValue::Threedm(crate::threedm::SetField::SupportedEvents(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_device_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::DeviceStatus| {
            FieldValue::Threedm(crate::threedm::SetField::DeviceStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_device_status_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::threedm::DeviceStatusResponse| {
            FieldValue::Threedm(crate::threedm::SetField::DeviceStatusResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_reset_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ResetFilter| {
            FieldValue::Filter(crate::filter::SetField::ResetFilter(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_set_initial_attitude(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SetInitialAttitude| {
            FieldValue::Filter(crate::filter::SetField::SetInitialAttitude(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_set_initial_heading(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SetInitialHeading| {
            FieldValue::Filter(crate::filter::SetField::SetInitialHeading(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_run_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::RunFilter| {
            FieldValue::Filter(crate::filter::SetField::RunFilter(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_vehicle_dynamics_mode(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::VehicleDynamicsMode| {
            FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_vehicle_dynamics_mode_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::VehicleDynamicsModeResponse| {
            FieldValue::Filter(crate::filter::SetField::VehicleDynamicsModeResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_transform(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SensorToVehicleTransform| {
            FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_transform_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::SensorToVehicleTransformResponse| {
                FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransformResponse(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SensorToVehicleOffset| {
            FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SensorToVehicleOffsetResponse| {
            FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffsetResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_antenna_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AntennaOffset| {
            FieldValue::Filter(crate::filter::SetField::AntennaOffset(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_antenna_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AntennaOffsetResponse| {
            FieldValue::Filter(crate::filter::SetField::AntennaOffsetResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_estimation_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::EstimationControl| {
            FieldValue::Filter(crate::filter::SetField::EstimationControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_estimation_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::EstimationControlResponse| {
            FieldValue::Filter(crate::filter::SetField::EstimationControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gnss_source_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GnssSourceControl| {
            FieldValue::Filter(crate::filter::SetField::GnssSourceControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gnss_source_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GnssSourceControlResponse| {
            FieldValue::Filter(crate::filter::SetField::GnssSourceControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_external_gnss_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ExternalGnssUpdate| {
            FieldValue::Filter(crate::filter::SetField::ExternalGnssUpdate(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_external_heading_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ExternalHeadingUpdate| {
            FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdate(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_heading_update_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::HeadingUpdateControl| {
            FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_heading_update_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::HeadingUpdateControlResponse| {
            FieldValue::Filter(crate::filter::SetField::HeadingUpdateControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_auto_init_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AutoInitControl| {
            FieldValue::Filter(crate::filter::SetField::AutoInitControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_auto_init_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AutoInitControlResponse| {
            FieldValue::Filter(crate::filter::SetField::AutoInitControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_accel_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AccelNoise| {
            FieldValue::Filter(crate::filter::SetField::AccelNoise(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_accel_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AccelNoiseResponse| {
            FieldValue::Filter(crate::filter::SetField::AccelNoiseResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gyro_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GyroNoise| {
            FieldValue::Filter(crate::filter::SetField::GyroNoise(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gyro_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GyroNoiseResponse| {
            FieldValue::Filter(crate::filter::SetField::GyroNoiseResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_accel_bias_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AccelBiasModel| {
            FieldValue::Filter(crate::filter::SetField::AccelBiasModel(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_accel_bias_model_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AccelBiasModelResponse| {
            FieldValue::Filter(crate::filter::SetField::AccelBiasModelResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gyro_bias_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GyroBiasModel| {
            FieldValue::Filter(crate::filter::SetField::GyroBiasModel(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gyro_bias_model_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GyroBiasModelResponse| {
            FieldValue::Filter(crate::filter::SetField::GyroBiasModelResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_zupt_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ZuptControl| {
            FieldValue::Filter(crate::filter::SetField::ZuptControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_zupt_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ZuptControlResponse| {
            FieldValue::Filter(crate::filter::SetField::ZuptControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_external_heading_update_with_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ExternalHeadingUpdateWithTime| {
            FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdateWithTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_zero_angular_rate_update_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ZeroAngularRateUpdateControl| {
            FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_zero_angular_rate_update_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::ZeroAngularRateUpdateControlResponse| {
                FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControlResponse(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_tare_orientation(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::TareOrientation| {
            FieldValue::Filter(crate::filter::SetField::TareOrientation(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_commanded_zupt(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::CommandedZupt| {
            FieldValue::Filter(crate::filter::SetField::CommandedZupt(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_commanded_zero_angular_rate_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::CommandedZeroAngularRateUpdate| {
            FieldValue::Filter(crate::filter::SetField::CommandedZeroAngularRateUpdate(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_mag_capture_auto_calibration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MagCaptureAutoCalibration| {
            FieldValue::Filter(crate::filter::SetField::MagCaptureAutoCalibration(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gravity_noise_std_dev(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GravityNoiseStdDev| {
            FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gravity_noise_std_dev_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GravityNoiseStdDevResponse| {
            FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDevResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_pressure_altitude_noise_std_dev(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::PressureAltitudeNoiseStdDev| {
            FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_pressure_altitude_noise_std_dev_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::PressureAltitudeNoiseStdDevResponse| {
                FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDevResponse(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_hard_iron_offset_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::HardIronOffsetNoise| {
            FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_hard_iron_offset_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::HardIronOffsetNoiseResponse| {
            FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoiseResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_soft_iron_matrix_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SoftIronMatrixNoise| {
            FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_soft_iron_matrix_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SoftIronMatrixNoiseResponse| {
            FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoiseResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_mag_noise_std_dev(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MagNoiseStdDev| {
            FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_mag_noise_std_dev_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MagNoiseStdDevResponse| {
            FieldValue::Filter(crate::filter::SetField::MagNoiseStdDevResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_declination_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::DeclinationSource| {
            FieldValue::Filter(crate::filter::SetField::DeclinationSource(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_declination_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::DeclinationSourceResponse| {
            FieldValue::Filter(crate::filter::SetField::DeclinationSourceResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gravity_magnitude_adaptive_measurement(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::GravityMagnitudeAdaptiveMeasurement| {
                FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_gravity_magnitude_adaptive_measurement_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::GravityMagnitudeAdaptiveMeasurementResponse| {
                FieldValue::Filter(
                    crate::filter::SetField::GravityMagnitudeAdaptiveMeasurementResponse(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_mag_magnitude_adaptive_measurement(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MagMagnitudeAdaptiveMeasurement| {
            FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_mag_magnitude_adaptive_measurement_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::MagMagnitudeAdaptiveMeasurementResponse| {
                FieldValue::Filter(
                    crate::filter::SetField::MagMagnitudeAdaptiveMeasurementResponse(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_mag_dip_angle_adaptive_measurement(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MagDipAngleAdaptiveMeasurement| {
            FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_mag_dip_angle_adaptive_measurement_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::MagDipAngleAdaptiveMeasurementResponse| {
                FieldValue::Filter(
                    crate::filter::SetField::MagDipAngleAdaptiveMeasurementResponse(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_altitude_aiding_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AltitudeAidingControl| {
            FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_altitude_aiding_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AltitudeAidingControlResponse| {
            FieldValue::Filter(crate::filter::SetField::AltitudeAidingControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_pitch_roll_aiding_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::PitchRollAidingControl| {
            FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_pitch_roll_aiding_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::PitchRollAidingControlResponse| {
            FieldValue::Filter(crate::filter::SetField::PitchRollAidingControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_inclination_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::InclinationSource| {
            FieldValue::Filter(crate::filter::SetField::InclinationSource(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_inclination_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::InclinationSourceResponse| {
            FieldValue::Filter(crate::filter::SetField::InclinationSourceResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_magnetic_field_magnitude_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MagneticFieldMagnitudeSource| {
            FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_magnetic_field_magnitude_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::MagneticFieldMagnitudeSourceResponse| {
                FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSourceResponse(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_aiding_measurement_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AidingMeasurementControl| {
            FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_aiding_measurement_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::AidingMeasurementControlResponse| {
                FieldValue::Filter(crate::filter::SetField::AidingMeasurementControlResponse(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_initialization_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::InitializationConfiguration| {
            FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_initialization_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::InitializationConfigurationResponse| {
                FieldValue::Filter(crate::filter::SetField::InitializationConfigurationResponse(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_adaptive_filter_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AdaptiveFilterControl| {
            FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_adaptive_filter_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::AdaptiveFilterControlResponse| {
            FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_multi_antenna_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MultiAntennaOffset| {
            FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_multi_antenna_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::MultiAntennaOffsetResponse| {
            FieldValue::Filter(crate::filter::SetField::MultiAntennaOffsetResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_relative_position_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::RelativePositionConfiguration| {
            FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_relative_position_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::RelativePositionConfigurationResponse| {
                FieldValue::Filter(
                    crate::filter::SetField::RelativePositionConfigurationResponse(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_reference_point_lever_arm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ReferencePointLeverArm| {
            FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_reference_point_lever_arm_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::ReferencePointLeverArmResponse| {
            FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArmResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_speed_lever_arm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SpeedLeverArm| {
            FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_speed_lever_arm_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::SpeedLeverArmResponse| {
            FieldValue::Filter(crate::filter::SetField::SpeedLeverArmResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_wheeled_vehicle_constraint_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::WheeledVehicleConstraintControl| {
            FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_wheeled_vehicle_constraint_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::WheeledVehicleConstraintControlResponse| {
                FieldValue::Filter(
                    crate::filter::SetField::WheeledVehicleConstraintControlResponse(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_gnss_antenna_calibration_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter::GnssAntennaCalibrationControl| {
            FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gnss_antenna_calibration_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter::GnssAntennaCalibrationControlResponse| {
                FieldValue::Filter(
                    crate::filter::SetField::GnssAntennaCalibrationControlResponse(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss::ReceiverInfo| {
            FieldValue::Gnss(crate::gnss::SetField::ReceiverInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_info_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss::ReceiverInfoResponse| {
            FieldValue::Gnss(crate::gnss::SetField::ReceiverInfoResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_signal_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss::SignalConfiguration| {
            FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_signal_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss::SignalConfigurationResponse| {
            FieldValue::Gnss(crate::gnss::SetField::SignalConfigurationResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_spartn_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss::SpartnConfiguration| {
            FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_spartn_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss::SpartnConfigurationResponse| {
            FieldValue::Gnss(crate::gnss::SetField::SpartnConfigurationResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_frame_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::FrameConfig| {
            FieldValue::Aiding(crate::aiding::SetField::FrameConfig(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_frame_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::FrameConfigResponse| {
            FieldValue::Aiding(crate::aiding::SetField::FrameConfigResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_echo_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::EchoControl| {
            FieldValue::Aiding(crate::aiding::SetField::EchoControl(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_echo_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::EchoControlResponse| {
            FieldValue::Aiding(crate::aiding::SetField::EchoControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::EcefPosition| {
            FieldValue::Aiding(crate::aiding::SetField::EcefPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::LlhPosition| {
            FieldValue::Aiding(crate::aiding::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_height_above_ellipsoid(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::HeightAboveEllipsoid| {
            FieldValue::Aiding(crate::aiding::SetField::HeightAboveEllipsoid(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::EcefVelocity| {
            FieldValue::Aiding(crate::aiding::SetField::EcefVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::NedVelocity| {
            FieldValue::Aiding(crate::aiding::SetField::NedVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_body_frame_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::BodyFrameVelocity| {
            FieldValue::Aiding(crate::aiding::SetField::BodyFrameVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_true_heading(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::TrueHeading| {
            FieldValue::Aiding(crate::aiding::SetField::TrueHeading(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_magnetic_field(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::MagneticField| {
            FieldValue::Aiding(crate::aiding::SetField::MagneticField(v))
        })
    }

    #[inline(never)]
    pub(super) fn aiding_pressure(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::aiding::Pressure| {
            FieldValue::Aiding(crate::aiding::SetField::Pressure(v))
        })
    }

    #[inline(never)]
    pub(super) fn system_communication_mode(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::system::CommunicationMode| {
            FieldValue::System(crate::system::SetField::CommunicationMode(v))
        })
    }

    #[inline(never)]
    pub(super) fn system_communication_mode_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::system::CommunicationModeResponse| {
            FieldValue::System(crate::system::SetField::CommunicationModeResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::ScaledAccel| {
            FieldValue::Sensor(crate::sensor::SetField::ScaledAccel(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_gyro(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::ScaledGyro| {
            FieldValue::Sensor(crate::sensor::SetField::ScaledGyro(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_mag(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::ScaledMag| {
            FieldValue::Sensor(crate::sensor::SetField::ScaledMag(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_delta_theta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::DeltaTheta| {
            FieldValue::Sensor(crate::sensor::SetField::DeltaTheta(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_delta_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::DeltaVelocity| {
            FieldValue::Sensor(crate::sensor::SetField::DeltaVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_cf_orientation_matrix(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::CfOrientationMatrix| {
            FieldValue::Sensor(crate::sensor::SetField::CfOrientationMatrix(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_cf_quaternion(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::CfQuaternion| {
            FieldValue::Sensor(crate::sensor::SetField::CfQuaternion(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_cf_euler_angles(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::CfEulerAngles| {
            FieldValue::Sensor(crate::sensor::SetField::CfEulerAngles(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_cf_stabilized_north(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::CfStabilizedNorth| {
            FieldValue::Sensor(crate::sensor::SetField::CfStabilizedNorth(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_cf_stabilized_up(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::CfStabilizedUp| {
            FieldValue::Sensor(crate::sensor::SetField::CfStabilizedUp(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_gps_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::GpsTimestamp| {
            FieldValue::Sensor(crate::sensor::SetField::GpsTimestamp(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_temperature_statistics(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::TemperatureStatistics| {
            FieldValue::Sensor(crate::sensor::SetField::TemperatureStatistics(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_pressure(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::ScaledPressure| {
            FieldValue::Sensor(crate::sensor::SetField::ScaledPressure(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_overrange_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::OverrangeStatus| {
            FieldValue::Sensor(crate::sensor::SetField::OverrangeStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn sensor_odometer_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::sensor::OdometerData| {
            FieldValue::Sensor(crate::sensor::SetField::OdometerData(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::LlhPosition| {
            FieldValue::GnssData(crate::gnss_data::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::EcefPosition| {
            FieldValue::GnssData(crate::gnss_data::SetField::EcefPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::NedVelocity| {
            FieldValue::GnssData(crate::gnss_data::SetField::NedVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::EcefVelocity| {
            FieldValue::GnssData(crate::gnss_data::SetField::EcefVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_dop(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::Dop| {
            FieldValue::GnssData(crate::gnss_data::SetField::Dop(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::UtcTime| {
            FieldValue::GnssData(crate::gnss_data::SetField::UtcTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::GpsTime| {
            FieldValue::GnssData(crate::gnss_data::SetField::GpsTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_clock_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::ClockInfo| {
            FieldValue::GnssData(crate::gnss_data::SetField::ClockInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::FixInfo| {
            FieldValue::GnssData(crate::gnss_data::SetField::FixInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_sv_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::SvInfo| {
            FieldValue::GnssData(crate::gnss_data::SetField::SvInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_hardware_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::HardwareStatus| {
            FieldValue::GnssData(crate::gnss_data::SetField::HardwareStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_dgnss_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::DgnssInfo| {
            FieldValue::GnssData(crate::gnss_data::SetField::DgnssInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_data_dgnss_channel_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_data::DgnssChannelStatus| {
            FieldValue::GnssData(crate::gnss_data::SetField::DgnssChannelStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::LlhPosition| {
            FieldValue::FilterData(crate::filter_data::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::NedVelocity| {
            FieldValue::FilterData(crate::filter_data::SetField::NedVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_attitude_quaternion(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::AttitudeQuaternion| {
            FieldValue::FilterData(crate::filter_data::SetField::AttitudeQuaternion(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_attitude_dcm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::AttitudeDcm| {
            FieldValue::FilterData(crate::filter_data::SetField::AttitudeDcm(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_euler_angles(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::EulerAngles| {
            FieldValue::FilterData(crate::filter_data::SetField::EulerAngles(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GyroBias| {
            FieldValue::FilterData(crate::filter_data::SetField::GyroBias(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::AccelBias| {
            FieldValue::FilterData(crate::filter_data::SetField::AccelBias(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_llh_position_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::LlhPositionUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::LlhPositionUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_ned_velocity_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::NedVelocityUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::NedVelocityUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_euler_angles_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::EulerAnglesUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::EulerAnglesUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_bias_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GyroBiasUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::GyroBiasUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_bias_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::AccelBiasUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::AccelBiasUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_linear_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::LinearAccel| {
            FieldValue::FilterData(crate::filter_data::SetField::LinearAccel(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_comp_angular_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::CompAngularRate| {
            FieldValue::FilterData(crate::filter_data::SetField::CompAngularRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_wgs84_gravity_magnitude(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::Wgs84GravityMagnitude| {
            FieldValue::FilterData(crate::filter_data::SetField::Wgs84GravityMagnitude(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_filter_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::filter_data::FilterStatus::decode_data(data, device)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::FilterStatus(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_gps_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GpsTimestamp| {
            FieldValue::FilterData(crate::filter_data::SetField::GpsTimestamp(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_quaternion_attitude_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::QuaternionAttitudeUncertainty| {
                FieldValue::FilterData(crate::filter_data::SetField::QuaternionAttitudeUncertainty(
                    v,
                ))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_gravity_vector(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GravityVector| {
            FieldValue::FilterData(crate::filter_data::SetField::GravityVector(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_heading_update_state(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::HeadingUpdateState| {
            FieldValue::FilterData(crate::filter_data::SetField::HeadingUpdateState(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_magnetic_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::MagneticModel| {
            FieldValue::FilterData(crate::filter_data::SetField::MagneticModel(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_scale_factor(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GyroScaleFactor| {
            FieldValue::FilterData(crate::filter_data::SetField::GyroScaleFactor(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_scale_factor(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::AccelScaleFactor| {
            FieldValue::FilterData(crate::filter_data::SetField::AccelScaleFactor(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_scale_factor_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GyroScaleFactorUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::GyroScaleFactorUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_scale_factor_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::AccelScaleFactorUncertainty| {
                FieldValue::FilterData(crate::filter_data::SetField::AccelScaleFactorUncertainty(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_compensated_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::CompensatedAccel| {
            FieldValue::FilterData(crate::filter_data::SetField::CompensatedAccel(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_standard_atmosphere(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::StandardAtmosphere| {
            FieldValue::FilterData(crate::filter_data::SetField::StandardAtmosphere(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_pressure_altitude(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::PressureAltitude| {
            FieldValue::FilterData(crate::filter_data::SetField::PressureAltitude(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_hard_iron_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::MagAutoHardIronOffset| {
            FieldValue::FilterData(crate::filter_data::SetField::MagAutoHardIronOffset(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_soft_iron_matrix(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::MagAutoSoftIronMatrix| {
            FieldValue::FilterData(crate::filter_data::SetField::MagAutoSoftIronMatrix(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_hard_iron_offset_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::MagAutoHardIronOffsetUncertainty| {
                FieldValue::FilterData(
                    crate::filter_data::SetField::MagAutoHardIronOffsetUncertainty(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_soft_iron_matrix_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::MagAutoSoftIronMatrixUncertainty| {
                FieldValue::FilterData(
                    crate::filter_data::SetField::MagAutoSoftIronMatrixUncertainty(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_antenna_offset_correction(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::GnssAntennaOffsetCorrection| {
                FieldValue::FilterData(crate::filter_data::SetField::GnssAntennaOffsetCorrection(v))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_antenna_offset_correction_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::GnssAntennaOffsetCorrectionUncertainty| {
                FieldValue::FilterData(
                    crate::filter_data::SetField::GnssAntennaOffsetCorrectionUncertainty(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_multi_antenna_offset_correction(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::MultiAntennaOffsetCorrection| {
                FieldValue::FilterData(crate::filter_data::SetField::MultiAntennaOffsetCorrection(
                    v,
                ))
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_multi_antenna_offset_correction_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::MultiAntennaOffsetCorrectionUncertainty| {
                FieldValue::FilterData(
                    crate::filter_data::SetField::MultiAntennaOffsetCorrectionUncertainty(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_position_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::EcefPositionUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::EcefPositionUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_velocity_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::EcefVelocityUncertainty| {
            FieldValue::FilterData(crate::filter_data::SetField::EcefVelocityUncertainty(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::EcefPosition| {
            FieldValue::FilterData(crate::filter_data::SetField::EcefPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::EcefVelocity| {
            FieldValue::FilterData(crate::filter_data::SetField::EcefVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_ned_relative_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::NedRelativePosition| {
            FieldValue::FilterData(crate::filter_data::SetField::NedRelativePosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_position_aiding_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GnssPositionAidingStatus| {
            FieldValue::FilterData(crate::filter_data::SetField::GnssPositionAidingStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_aiding_measurement_summary(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::AidingMeasurementSummary| {
            FieldValue::FilterData(crate::filter_data::SetField::AidingMeasurementSummary(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_odometer_scale_factor_error(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::OdometerScaleFactorError| {
            FieldValue::FilterData(crate::filter_data::SetField::OdometerScaleFactorError(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_odometer_scale_factor_error_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::OdometerScaleFactorErrorUncertainty| {
                FieldValue::FilterData(
                    crate::filter_data::SetField::OdometerScaleFactorErrorUncertainty(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_dual_antenna_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::GnssDualAntennaStatus| {
            FieldValue::FilterData(crate::filter_data::SetField::GnssDualAntennaStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_aiding_frame_config_error(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::filter_data::AidingFrameConfigError| {
            FieldValue::FilterData(crate::filter_data::SetField::AidingFrameConfigError(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_aiding_frame_config_error_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(
            data,
            |v: crate::filter_data::AidingFrameConfigErrorUncertainty| {
                FieldValue::FilterData(
                    crate::filter_data::SetField::AidingFrameConfigErrorUncertainty(v),
                )
            },
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::LlhPosition| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::EcefPosition| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::EcefPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::NedVelocity| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::NedVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::EcefVelocity| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::EcefVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_dop(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::Dop| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::Dop(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::UtcTime| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::UtcTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::GpsTime| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GpsTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::FixInfo| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::FixInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_hardware_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::HardwareStatus| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::HardwareStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_clock_info_2(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::ClockInfo2| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::ClockInfo2(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_gps_leap_seconds(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::GpsLeapSeconds| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GpsLeapSeconds(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_sbas_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::SbasInfo| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::SbasInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_satellite_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::SatelliteStatus| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::SatelliteStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_raw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::Raw| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::Raw(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_gps_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::GpsEphemeris| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GpsEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_glonass_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::GlonassEphemeris| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GlonassEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_galileo_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::GalileoEphemeris| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GalileoEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_beidou_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_1::BeidouEphemeris| {
            FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::BeidouEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::LlhPosition| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::EcefPosition| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::EcefPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::NedVelocity| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::NedVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::EcefVelocity| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::EcefVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_dop(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::Dop| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::Dop(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::UtcTime| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::UtcTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::GpsTime| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GpsTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::FixInfo| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::FixInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_hardware_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::HardwareStatus| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::HardwareStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_clock_info_2(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::ClockInfo2| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::ClockInfo2(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_gps_leap_seconds(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::GpsLeapSeconds| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GpsLeapSeconds(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_sbas_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::SbasInfo| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::SbasInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_satellite_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::SatelliteStatus| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::SatelliteStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_raw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::Raw| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::Raw(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_gps_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::GpsEphemeris| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GpsEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_glonass_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::GlonassEphemeris| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GlonassEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_galileo_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::GalileoEphemeris| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GalileoEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_beidou_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_receiver_2::BeidouEphemeris| {
            FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::BeidouEphemeris(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_corrections_base_station_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_corrections::BaseStationInfo| {
            FieldValue::GnssCorrections(crate::gnss_corrections::SetField::BaseStationInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_corrections_rtk_corrections_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_corrections::RtkCorrectionsStatus| {
            FieldValue::GnssCorrections(crate::gnss_corrections::SetField::RtkCorrectionsStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_external_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_external::LlhPosition| {
            FieldValue::GnssExternal(crate::gnss_external::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_external_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_external::NedVelocity| {
            FieldValue::GnssExternal(crate::gnss_external::SetField::NedVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_external_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_external::UtcTime| {
            FieldValue::GnssExternal(crate::gnss_external::SetField::UtcTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_external_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_external::FixInfo| {
            FieldValue::GnssExternal(crate::gnss_external::SetField::FixInfo(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_external_satellite_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::gnss_external::SatelliteStatus| {
            FieldValue::GnssExternal(crate::gnss_external::SetField::SatelliteStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn system_data_built_in_test(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::system_data::BuiltInTest| {
            FieldValue::SystemData(crate::system_data::SetField::BuiltInTest(v))
        })
    }

    #[inline(never)]
    pub(super) fn system_data_time_sync_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::system_data::TimeSyncStatus| {
            FieldValue::SystemData(crate::system_data::SetField::TimeSyncStatus(v))
        })
    }

    #[inline(never)]
    pub(super) fn system_data_gpio_state(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::system_data::GpioState| {
            FieldValue::SystemData(crate::system_data::SetField::GpioState(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_event_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::EventSource| {
            FieldValue::Shared(crate::shared::SetField::EventSource(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_gps_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::GpsTimestamp| {
            FieldValue::Shared(crate::shared::SetField::GpsTimestamp(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_delta_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::DeltaTime| {
            FieldValue::Shared(crate::shared::SetField::DeltaTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_reference_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::ReferenceTimestamp| {
            FieldValue::Shared(crate::shared::SetField::ReferenceTimestamp(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_reference_time_delta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::ReferenceTimeDelta| {
            FieldValue::Shared(crate::shared::SetField::ReferenceTimeDelta(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_external_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::ExternalTimestamp| {
            FieldValue::Shared(crate::shared::SetField::ExternalTimestamp(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_external_time_delta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::ExternalTimeDelta| {
            FieldValue::Shared(crate::shared::SetField::ExternalTimeDelta(v))
        })
    }
}

/// Writes the canonical JSON of one field: decoded, or raw with the decode error.
pub fn write_field_json(
    w: &mut dyn Write,
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> fmt::Result {
    match decode_field(set, descriptor, data, device) {
        Ok(value) => value.write_json(w),
        Err(error) => {
            w.write_char('{')?;
            write!(w, "\"descriptor\":{descriptor},\"data\":\"")?;
            json::write_hex(w, data)?;
            w.write_str("\",\"error\":")?;
            json::write_display(w, &error)?;
            w.write_char('}')
        }
    }
}

/// Writes the canonical JSON line of a packet found at stream offset `offset` (no newline).
pub fn write_packet_json(
    w: &mut dyn Write,
    offset: u64,
    packet: &Packet<'_>,
    device: Option<Device>,
) -> fmt::Result {
    let set = packet.set();
    w.write_char('{')?;
    write!(w, "\"offset\":{offset},\"set\":{set},\"fields\":[")?;
    for (i, item) in packet.fields().enumerate() {
        if i > 0 {
            w.write_char(',')?;
        }
        match item {
            FieldItem::Field { descriptor, data } => {
                write_field_json(w, set, descriptor, data, device)?
            }
            FieldItem::Trailing { bytes, error } => {
                w.write_str("{\"trailing\":\"")?;
                json::write_hex(w, bytes)?;
                w.write_str("\",\"error\":")?;
                json::write_display(w, &error)?;
                w.write_char('}')?;
            }
        }
    }
    w.write_str("]}")
}

/// Writes the canonical JSON line of a skip run (no newline).
pub fn write_skip_json(w: &mut dyn Write, offset: u64, bytes: &[u8]) -> fmt::Result {
    w.write_char('{')?;
    write!(w, "\"offset\":{offset},\"skipped\":\"")?;
    json::write_hex(w, bytes)?;
    w.write_str("\"}")
}

/// Writes the canonical JSON line of a foreign frame (no newline; `docs/conformance.md` §5): an
/// NMEA sentence without its CR LF, or an RTCM3 frame's message number and payload length.
pub fn write_foreign_json(w: &mut dyn Write, offset: u64, bytes: &[u8]) -> fmt::Result {
    w.write_char('{')?;
    if bytes[0] == 0xD3 {
        let kind = crate::parser::rtcm_type(bytes);
        write!(
            w,
            "\"offset\":{offset},\"rtcm\":{kind},\"length\":{}",
            bytes.len() - 6
        )?;
        return w.write_char('}');
    }
    write!(w, "\"offset\":{offset},\"nmea\":\"")?;
    for &b in &bytes[..bytes.len() - 2] {
        if b == b'"' || b == b'\\' {
            w.write_char('\\')?;
        }
        w.write_char(char::from(b))?;
    }
    w.write_str("\"}")
}

/// Error unless `device` is `None` (for fields without per-device layouts).
#[cfg(feature = "std")]
pub fn no_device(device: Option<Device>) -> Result<(), crate::json_read::JsonError> {
    match device {
        None => Ok(()),
        Some(d) => Err(crate::json_read::JsonError::new(std::format!(
            "this field has no per-device layouts (got device {})",
            d.id()
        ))
        .at("device")),
    }
}
