//! The Rust runtime contract (docs/runtime-contract.md, "Rust"): every item the runtime (src/)
//! takes from the generated modules `framing`, `dispatch` and `commands`, bound here with the
//! type the runtime uses it at. Compiled against the crate the back end renders from
//! tests/runtime_specs/ (tests/lang/rust.sh runtime): a template that drops or retypes one of
//! them fails this build, whatever protocol the crate is for.

use core::fmt::{self, Write};

use protocodec::dispatch::{self, Device, FieldValue};
use protocodec::error::DecodeError;
use protocodec::fields::Packet;
use protocodec::json_read::{Json, JsonError};
use protocodec::session::CommandFacts;
use protocodec::{commands, framing};

/// `dispatch::decode_field`.
type DecodeFn = fn(u8, u8, &[u8], Option<Device>) -> Result<FieldValue, DecodeError>;
/// `dispatch::write_field_json`.
type WriteFieldFn = fn(&mut dyn Write, u8, u8, &[u8], Option<Device>) -> fmt::Result;
/// `dispatch::write_packet_json`.
type WritePacketFn = fn(&mut dyn Write, u64, &Packet<'_>, Option<Device>) -> fmt::Result;
/// `FieldValue::from_json`.
type FromJsonFn = fn(u8, u8, Option<Device>, &Json) -> Result<FieldValue, JsonError>;

#[test]
fn framing_provides_the_constants_the_runtime_reads() {
    let sync: &[u8] = &framing::SYNC;
    let sizes: [usize; 15] = [
        framing::HEADER_SIZE,
        framing::SET_OFFSET,
        framing::LENGTH_OFFSET,
        framing::MAX_PAYLOAD,
        framing::CHECKSUM_SIZE,
        framing::MAX_PACKET,
        framing::FIELD_HEADER_SIZE,
        framing::FIELD_LENGTH_OFFSET,
        framing::FIELD_DESCRIPTOR_OFFSET,
        framing::FIELD_LENGTH_ADJUST,
        framing::MAX_FIELD_DATA,
        framing::PATH_DEPTH,
        framing::MAX_KEY,
        framing::CLOCK_BUCKETS,
        framing::CLOCK_MIN_BUCKETS,
    ];
    let clock_ns: [i64; 2] = [framing::CLOCK_BUCKET_NS, framing::CLOCK_RESTART_NS];
    assert!(clock_ns.iter().all(|&n| n > 0));
    let flags: [bool; 3] = [
        framing::FIELD_LENGTH_COUNTS_HEADER,
        framing::BIG_ENDIAN,
        framing::CHECKSUM_SUM1_FIRST,
    ];
    let adjust: fn(u8, u8) -> isize = framing::field_length_adjust;
    let data_sets: &[u8] = &framing::DATA_SETS;
    let first_shared: u16 = framing::FIRST_SHARED;
    let timestamps: &[(u8, usize)] = &framing::TIMESTAMPS;
    // What the runtime relies on beyond the types.
    assert_eq!(
        sizes[0],
        sync.len() + 2,
        "header: sync, set, payload length"
    );
    assert_eq!(
        framing::MAX_PACKET,
        framing::HEADER_SIZE + framing::MAX_PAYLOAD + framing::CHECKSUM_SIZE
    );
    assert_eq!(
        framing::MAX_FIELD_DATA,
        framing::MAX_PAYLOAD - framing::FIELD_HEADER_SIZE
    );
    assert_eq!(
        adjust(0, 0),
        framing::FIELD_LENGTH_ADJUST as isize,
        "{flags:?}"
    );
    assert!(data_sets.windows(2).all(|w| w[0] < w[1]));
    assert!(first_shared <= 0x100 && timestamps.iter().all(|t| t.1 <= framing::MAX_KEY));
}

#[test]
fn framing_provides_the_link_facts() {
    let commands: [Option<(u8, u8)>; 3] =
        [framing::LINK_IDLE, framing::LINK_PING, framing::LINK_RESUME];
    let attempts: u32 = framing::LINK_IDLE_ATTEMPTS;
    let settle: Option<u32> = framing::LINK_BAUD_SETTLE_MS;
    let has_bandwidth: bool = framing::LINK_HAS_BANDWIDTH;
    let bandwidth: [u32; 3] = [
        framing::LINK_UART_WORD_BITS,
        framing::LINK_PACKET_OVERHEAD,
        framing::LINK_FIELD_OVERHEAD,
    ];
    assert!(attempts >= 1, "{commands:?} {settle:?}");
    assert_eq!(has_bandwidth, bandwidth[0] != 0);
}

#[test]
fn dispatch_provides_devices_values_and_the_json_writers() {
    let all: &[Device] = &Device::ALL;
    let id: fn(Device) -> &'static str = Device::id;
    let from_id: fn(&str) -> Option<Device> = Device::from_id;
    let title: fn(Device) -> &'static str = Device::title;
    let manual: fn(Device) -> &'static str = Device::manual;
    let supports: fn(Device, u8, u8) -> bool = Device::supports;
    let baud_rates: fn(Device) -> &'static [u32] = Device::baud_rates;
    let default_baud: fn(Device) -> Option<u32> = Device::default_baud;
    for &d in all {
        assert!(baud_rates(d).windows(2).all(|w| w[0] < w[1]));
        if let Some(b) = default_baud(d) {
            assert!(baud_rates(d).contains(&b));
        }
        assert_eq!(from_id(id(d)), Some(d));
        assert!(!title(d).is_empty() && !manual(d).is_empty());
        let _ = supports(d, 0, 0);
    }
    let decode: DecodeFn = dispatch::decode_field;
    let descriptor: fn(&FieldValue) -> u8 = FieldValue::descriptor;
    let name: fn(&FieldValue) -> &'static str = FieldValue::name;
    let write_json: fn(&FieldValue, &mut dyn Write) -> fmt::Result = FieldValue::write_json;
    let write_field: WriteFieldFn = dispatch::write_field_json;
    let write_packet: WritePacketFn = dispatch::write_packet_json;
    let write_skip: fn(&mut dyn Write, u64, &[u8]) -> fmt::Result = dispatch::write_skip_json;
    let _ = (
        decode,
        descriptor,
        name,
        write_json,
        write_field,
        write_packet,
        write_skip,
    );
    let from_json: FromJsonFn = FieldValue::from_json;
    let _ = from_json;
}

#[test]
fn commands_provides_the_ack_rule_and_the_command_facts() {
    let ack_descriptor: u8 = commands::ACK_DESCRIPTOR;
    let ack_ok: u32 = commands::ACK_OK;
    let ack_of: fn(&FieldValue) -> Option<(u8, u32)> = commands::ack_of;
    let function_name: fn(u8) -> Option<&'static str> = commands::function_name;
    let function_devices: &[(u8, &[Device])] = commands::FUNCTION_DEVICES;
    let rows: &[CommandFacts] = &commands::COMMANDS;
    let facts: fn(&FieldValue) -> Option<&'static CommandFacts> = commands::command_facts;
    let function: fn(&FieldValue) -> Option<u8> = commands::command_function;
    let param: fn(&FieldValue, &str) -> Option<i64> = commands::command_param;
    let _ = (
        ack_descriptor,
        ack_ok,
        ack_of,
        function_name,
        facts,
        function,
        param,
    );
    assert!(!rows.is_empty() && function_devices.len() <= 256);
}
