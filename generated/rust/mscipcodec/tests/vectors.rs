//! Golden vectors (tests/vectors/mscip/): each case's bytes decode (whole, and fed one
//! byte at a time) to exactly the expected canonical JSON lines, and those lines encode back to
//! the bytes.
#![allow(dead_code)]

use mscipcodec::text::{decode_bytes, encode_text};
use mscipcodec::Device;

fn from_hex(hex: &str) -> Vec<u8> {
    (0..hex.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&hex[i..i + 2], 16).unwrap())
        .collect()
}

fn check(hex: &str, device: Option<&str>, expect: &[&str], rejected: bool) {
    let bytes = from_hex(hex);
    let device = device.map(|id| Device::from_id(id).expect("device of the vector"));
    let mut text = String::new();
    for line in expect {
        text.push_str(line);
        text.push('\n');
    }
    assert_eq!(
        decode_bytes(&bytes, device, usize::MAX),
        text,
        "decoding the whole input"
    );
    assert_eq!(
        decode_bytes(&bytes, device, 1),
        text,
        "decoding one byte at a time"
    );
    let encoded =
        encode_text(&text).unwrap_or_else(|(line, e)| panic!("encoding line {line}: {e}"));
    assert_eq!(
        encoded, bytes,
        "encoding the expected lines (rejected: {rejected})"
    );
}
