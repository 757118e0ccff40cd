//! Golden vectors (tests/vectors/demo/) and stream corpus (tests/streams/demo/):
//! each case's bytes decode (whole, and fed in chunks of every size) to exactly the expected
//! canonical JSON lines, and those lines encode back to the bytes.

use democodec::fields::{FieldItem, Packet};
use democodec::parser::{Event, Parser};
use democodec::text::{decode_bytes, encode_text};
use democodec::{decode_field, decode_packet, AnyPacket, Device, LayoutCache};

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
    for chunk in 1..bytes.len() {
        assert_eq!(
            decode_bytes(&bytes, device, chunk),
            text,
            "decoding in chunks of {chunk} bytes"
        );
    }
    let encoded =
        encode_text(&text).unwrap_or_else(|(line, e)| panic!("encoding line {line}: {e}"));
    assert_eq!(
        encoded, bytes,
        "encoding the expected lines (rejected: {rejected})"
    );
    check_packets(&bytes);
}

/// The JSON of a decoded field (compares floats as their canonical text, NaN included).
fn json_of(value: &democodec::FieldValue) -> String {
    let mut s = String::new();
    value.write_json(&mut s).expect("JSON of a field");
    s
}

/// What a straight-line decode gave: the fields decoded into members (descriptor, JSON) and the
/// entries that went to `other`, both in packet order.
#[derive(Debug, PartialEq)]
struct Straight {
    members: Vec<(u8, String)>,
    other: Vec<String>,
}

fn straight(any: &AnyPacket, other: Vec<String>, n: usize) -> Straight {
    let members: Vec<(u8, String)> = match any.index() {
        Some(index) => index
            .descriptors()
            .iter()
            .map(|&d| (d, json_of(&any.field(d).expect("a decoded member"))))
            .collect(),
        None => Vec::new(),
    };
    assert_eq!(members.len(), n, "the count returned is the index's");
    Straight { members, other }
}

/// Every packet of the case through the straight-line decoder (`decode_packet`) and the layout
/// cache (twice: the second time every shape it recorded is in it), against the general dispatch
/// (`decode_field` on each entry of the field iterator, device None): a field is decoded into its
/// member when it is the first of its descriptor, its set has a member for it and it decodes,
/// with decode_field's value; every other entry goes to `other`, in packet order.
fn check_packets(bytes: &[u8]) {
    let mut packets: Vec<Vec<u8>> = Vec::new();
    let mut parser = Parser::new();
    let mut on = |event: Event<'_>| {
        if let Event::Packet { bytes, .. } = event {
            packets.push(bytes.to_vec());
        }
    };
    parser.feed(bytes, &mut on);
    parser.flush(&mut on);
    let mut any = Box::new(AnyPacket::default());
    let mut cache = Box::new(LayoutCache::new());
    for pass in 0..2 {
        for bytes in &packets {
            let packet = Packet::new(bytes).expect("a packet the parser reported");
            let mut other = Vec::new();
            let n = decode_packet(bytes, &mut any, |item| other.push(format!("{item:?}")));
            let got = straight(&any, other, n);
            // the general dispatch
            let set = packet.set();
            let mut want = Straight {
                members: Vec::new(),
                other: Vec::new(),
            };
            let mut taken = [false; 256];
            for item in packet.fields() {
                match item {
                    FieldItem::Field { descriptor, data } => {
                        let d = usize::from(descriptor);
                        match decode_field(set, descriptor, data, None) {
                            Ok(general) if !taken[d] && any.has_member(descriptor) => {
                                taken[d] = true;
                                want.members.push((descriptor, json_of(&general)));
                            }
                            _ => want.other.push(format!("{item:?}")),
                        }
                    }
                    FieldItem::Trailing { .. } => want.other.push(format!("{item:?}")),
                }
            }
            assert_eq!(got, want, "straight-line decode of packet {bytes:02x?}");
            // the cache: the same result
            let mut other = Vec::new();
            let n = cache.decode(bytes, &mut any, |item| other.push(format!("{item:?}")));
            assert_eq!(
                straight(&any, other, n),
                want,
                "decode through the layout cache (pass {pass}) of packet {bytes:02x?}"
            );
        }
    }
}

/// `demo_ping_command` (tests/golden/vectors/demo/everything.yaml:11)
#[test]
fn case_demo_ping_command() {
    check(
        "a5a5010201004e23",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `demo_ack` (tests/golden/vectors/demo/everything.yaml:22)
#[test]
fn case_demo_ack() {
    check(
        "a5a5010480020100d2cd",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"echo\":1,\"code\":0}}]}",
        ],
        false,
    );
}

/// `demo_configure_write_gpio` (tests/golden/vectors/demo/everything.yaml:32)
#[test]
fn case_demo_configure_write_gpio() {
    check(
        "a5a501080206010101050100647f",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"configure\",\"values\":{\"function\":1,\"instance\":1,\"mode\":1,\"params\":{\"pin\":5,\"polarity\":true},\"suppress_ack\":false}}]}",
        ],
        false,
    );
}

/// `demo_configure_write_none` (tests/golden/vectors/demo/everything.yaml:45)
#[test]
fn case_demo_configure_write_none() {
    check(
        "a5a501060204010200015b9c",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"configure\",\"values\":{\"function\":1,\"instance\":2,\"mode\":0,\"params\":null,\"suppress_ack\":true}}]}",
        ],
        false,
    );
}

/// `demo_configure_read` (tests/golden/vectors/demo/everything.yaml:55)
#[test]
fn case_demo_configure_read() {
    check(
        "a5a501040202020358da",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"configure\",\"values\":{\"function\":2,\"instance\":3}}]}",
        ],
        false,
    );
}

/// `demo_configuration_response` (tests/golden/vectors/demo/everything.yaml:65)
#[test]
fn case_demo_configuration_response() {
    check(
        "a5a5017f827d0102006400c8616263000000000020202020202020202020206c6162656c3ff00000000000000000000000000000000000000000000000000000000000003ff00000000000000000000000000000000000000000000000000000000000003ff000000000000000000001ffffffff00000002fffffffe3001ffff78797a9f15",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":130,\"name\":\"configuration\",\"values\":{\"instance\":1,\"count\":2,\"rates\":[100,200],\"name\":\"abc\\u0000\\u0000\\u0000\\u0000\\u0000\",\"label\":\"           label\",\"matrix\":[1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0],\"fixed\":[1,-1,2,-2],\"flags\":12289,\"signed\":-1,\"tail\":[\"x\",\"y\",\"z\"]}}]}",
        ],
        false,
    );
}

/// `demo_per_device_dev_a` (tests/golden/vectors/demo/everything.yaml:97)
#[test]
fn case_demo_per_device_dev_a() {
    check(
        "a5a5010603040102030462ab",
        Some("dev_a"),
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"per_device\",\"device\":\"dev_a\",\"values\":{\"a\":16909060}}]}",
        ],
        false,
    );
}

/// `demo_per_device_dev_b_with_extra` (tests/golden/vectors/demo/everything.yaml:108)
#[test]
fn case_demo_per_device_dev_b_with_extra() {
    check(
        "a5a5010b03090000000000000001076ac6",
        Some("dev_b"),
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"per_device\",\"device\":\"dev_b\",\"values\":{\"b\":1,\"extra\":7}}]}",
        ],
        false,
    );
}

/// `demo_per_device_dev_b_without_extra` (tests/golden/vectors/demo/everything.yaml:119)
#[test]
fn case_demo_per_device_dev_b_without_extra() {
    check(
        "a5a5010a030800000000000000ff5f46",
        Some("dev_b"),
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"per_device\",\"device\":\"dev_b\",\"values\":{\"b\":255}}]}",
        ],
        false,
    );
}

/// `demo_sample_repeated` (tests/golden/vectors/demo/everything.yaml:130)
#[test]
fn case_demo_sample_repeated() {
    check(
        "a5a5903e011d3f8000000000000000000000000000000102030405060708fe3f000000011d0000000000000000000000003f80000000000000000000007fbf800000f1a4",
        None,
        &[
            "{\"offset\":0,\"set\":144,\"fields\":[{\"descriptor\":1,\"name\":\"sample\",\"values\":{\"quat\":[1.0,0.0,0.0,0.0],\"big\":72623859790382856,\"small\":-2,\"f\":0.5}},{\"descriptor\":1,\"name\":\"sample\",\"values\":{\"quat\":[0.0,0.0,0.0,1.0],\"big\":0,\"small\":127,\"f\":-1.0}}]}",
        ],
        false,
    );
}

/// `demo_receiver_1_shared_and_layout` (tests/golden/vectors/demo/everything.yaml:147)
#[test]
fn case_demo_receiver_1_shared_and_layout() {
    check(
        "a5a5911ed308000000003b9aca0003124046c00000000000c05e90000000000000037f56",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":211,\"name\":\"timestamp\",\"values\":{\"nanoseconds\":1000000000}},{\"descriptor\":3,\"name\":\"llh_position\",\"values\":{\"latitude\":45.5,\"longitude\":-122.25,\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `demo_receiver_2_same_layout` (tests/golden/vectors/demo/everything.yaml:161)
#[test]
fn case_demo_receiver_2_same_layout() {
    check(
        "a5a5921403124046c00000000000c05e9000000000000003fc84",
        None,
        &[
            "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":3,\"name\":\"llh_position\",\"values\":{\"latitude\":45.5,\"longitude\":-122.25,\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `demo_ping_bad_checksum` (tests/golden/vectors/demo/everything.yaml:171)
#[test]
fn case_demo_ping_bad_checksum() {
    check(
        "a5a5010201004f23",
        None,
        &["{\"offset\":0,\"skipped\":\"a5a5010201004f23\"}"],
        true,
    );
}
