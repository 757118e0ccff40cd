//! A consumer of a generated crate with its default features (`std`): builds a packet, decodes a
//! stream holding it into canonical JSON lines, encodes the lines back to the same bytes, and
//! prints the lines. Exit status 1 (and a message) when a step fails. `protocodec` stands for
//! the package name (tests/lang/rust.sh replaces it).

use std::process::ExitCode;

use protocodec::builder::PacketBuilder;
use protocodec::decode_field;
use protocodec::dispatch::set_defined;
use protocodec::text::{decode_bytes, encode_text};

fn run() -> Result<String, String> {
    // The first field that decodes from empty data, such as a command without parameters.
    let (set, descriptor, value) = (0..=255u8)
        .filter(|&set| set_defined(set))
        .find_map(|set| {
            (0..=255u8).find_map(|d| decode_field(set, d, &[], None).ok().map(|v| (set, d, v)))
        })
        .ok_or("no field decodes from empty data")?;
    let mut builder = PacketBuilder::new(set);
    builder
        .add_field_with(descriptor, |w| value.encode_data(w))
        .map_err(|e| format!("cannot build the packet: {e}"))?;
    let mut stream = vec![0x00];
    stream.extend_from_slice(builder.finish());

    let text = decode_bytes(&stream, None, 2);
    let lines: Vec<&str> = text.lines().collect();
    let want = format!("{{\"offset\":1,\"set\":{set},\"fields\":[{{\"descriptor\":{descriptor}");
    if lines.len() != 2
        || lines[0] != "{\"offset\":0,\"skipped\":\"00\"}"
        || !lines[1].starts_with(&want)
    {
        return Err(format!("unexpected JSON lines:\n{text}"));
    }
    if !lines[1].contains(&format!("\"name\":\"{}\"", value.name())) {
        return Err(format!(
            "the line does not name {}: {}",
            value.name(),
            lines[1]
        ));
    }
    let bytes =
        encode_text(&text).map_err(|(line, e)| format!("line {line} does not encode: {e}"))?;
    if bytes != stream {
        return Err(format!(
            "the lines encode to {bytes:02x?}, not {stream:02x?}"
        ));
    }
    Ok(text)
}

fn main() -> ExitCode {
    match run() {
        Ok(text) => {
            print!("{text}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("consumer-app: {message}");
            ExitCode::FAILURE
        }
    }
}
