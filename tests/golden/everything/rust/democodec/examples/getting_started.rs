//! `getting_started FILE`: builds a ping command with `democodec`, then decodes the
//! packets in FILE (read in blocks, as from a serial port) and prints the name of every field.
//! Run it with `cargo run --example getting_started -- FILE`. The documentation quotes the parts
//! between the `[...]` and `[end]` comments. Generated: do not edit.

use std::fs::File;
use std::io::Read;
use std::process::ExitCode;

use democodec::builder::PacketBuilder;
use democodec::commands_set::Ping;
use democodec::fields::{FieldItem, Packet};
use democodec::parser::{Event, Parser};

const PROG: &str = "getting_started";

// [build-command]
/// Builds the command with its typed value and prints the packet bytes.
fn print_command() -> Result<(), String> {
    let mut builder = PacketBuilder::new(Ping::SET);
    builder
        .add(&Ping {})
        .map_err(|e| format!("cannot build the command: {e}"))?;
    let hex: String = builder
        .finish()
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    println!("command {hex}");
    Ok(())
}
// [end]

// [parse-stream]
/// Prints one parser event: a packet with the names of its fields, or a run of skipped bytes.
fn on_event(event: Event<'_>) {
    match event {
        Event::Skip { count, .. } => println!("skipped {count}"),
        Event::Nmea { .. } | Event::Rtcm { .. } => {} // NMEA sentences, RTCM3 frames between packets
        Event::Packet { bytes, .. } => {
            let Some(packet) = Packet::new(bytes) else {
                return;
            };
            // A field that does not decode, or trailing bytes that are not a whole field, print "?".
            let names: Vec<&str> = packet
                .fields()
                .map(|item| match item {
                    FieldItem::Field { descriptor, data } => {
                        democodec::decode_field(packet.set(), descriptor, data, None)
                            .map_or("?", |value| value.name())
                    }
                    FieldItem::Trailing { .. } => "?",
                })
                .collect();
            println!(
                "packet set=0x{:02x} fields={}",
                packet.set(),
                names.join(",")
            );
        }
    }
}
// [end]

// [read-file]
/// Feeds the file to the parser block by block, then flushes it at the end of the input.
fn decode_file(path: &str) -> Result<(), String> {
    let mut file = File::open(path).map_err(|e| format!("cannot open {path}: {e}"))?;
    let mut parser = Parser::new();
    let mut block = [0u8; 4096];
    loop {
        let n = file
            .read(&mut block)
            .map_err(|e| format!("cannot read {path}: {e}"))?;
        if n == 0 {
            break;
        }
        parser.feed(&block[..n], on_event);
    }
    parser.flush(on_event);
    Ok(())
}
// [end]

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [path] = args.as_slice() else {
        eprintln!("usage: {PROG} FILE");
        return ExitCode::from(2);
    };
    match print_command().and_then(|()| decode_file(path)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("{PROG}: {message}");
            ExitCode::FAILURE
        }
    }
}
