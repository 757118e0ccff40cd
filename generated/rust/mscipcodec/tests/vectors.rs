//! Golden vectors (tests/vectors/mscip/) and stream corpus (tests/streams/mscip/):
//! each case's bytes decode (whole, and fed in chunks of every size) to exactly the expected
//! canonical JSON lines, and those lines encode back to the bytes.

use mscipcodec::fields::{FieldItem, Packet};
use mscipcodec::parser::{Event, Parser};
use mscipcodec::text::{decode_bytes, encode_text};
use mscipcodec::{decode_field, decode_packet, AnyPacket, Device, LayoutCache};

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
fn json_of(value: &mscipcodec::FieldValue) -> String {
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

/// `mscip_ping_command` (tests/vectors/mscip/base.yaml:10)
#[test]
fn case_mscip_ping_command() {
    check(
        "a5a5010202004f25",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_ping_reply` (tests/vectors/mscip/base.yaml:26)
#[test]
fn case_mscip_ping_reply() {
    check(
        "a5a5010480020200d3cf",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `get_device_messages_command` (tests/vectors/mscip/base.yaml:36)
#[test]
fn case_get_device_messages_command() {
    check(
        "a5a5010203005027",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"get_device_messages\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_device_messages_reply` (tests/vectors/mscip/base.yaml:46)
#[test]
fn case_get_device_messages_reply() {
    check(
        "a5a5010e80020300830801020103010401057b57",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"device_messages\",\"values\":{\"messages\":[{\"message_type\":1,\"message_code\":2},{\"message_type\":1,\"message_code\":3},{\"message_type\":1,\"message_code\":4},{\"message_type\":1,\"message_code\":5}]}}]}",
        ],
        false,
    );
}

/// `get_device_messages_reply_published` (tests/vectors/mscip/base.yaml:62)
#[test]
fn case_get_device_messages_reply_published() {
    check(
        "a5a5010f80030300830801020103010401057d73",
        None,
        &["{\"offset\":0,\"skipped\":\"a5a5010f80030300830801020103010401057d73\"}"],
        true,
    );
}

/// `get_device_messages_reply_table` (tests/vectors/mscip/base.yaml:78)
#[test]
fn case_get_device_messages_reply_table() {
    check(
        "a5a5010f80020300830801020103010401057d73",
        None,
        &["{\"offset\":0,\"skipped\":\"a5a5010f80020300830801020103010401057d73\"}"],
        true,
    );
}

/// `get_device_messages_reply_full` (tests/vectors/mscip/base.yaml:93)
#[test]
fn case_get_device_messages_reply_full() {
    check(
        "a5a5014080020300833a0102010301040105010601070108010902010203020402050206020702080209020a020b020c020da281a282a283a284a285a286a287a288a289d169",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"device_messages\",\"values\":{\"messages\":[{\"message_type\":1,\"message_code\":2},{\"message_type\":1,\"message_code\":3},{\"message_type\":1,\"message_code\":4},{\"message_type\":1,\"message_code\":5},{\"message_type\":1,\"message_code\":6},{\"message_type\":1,\"message_code\":7},{\"message_type\":1,\"message_code\":8},{\"message_type\":1,\"message_code\":9},{\"message_type\":2,\"message_code\":1},{\"message_type\":2,\"message_code\":3},{\"message_type\":2,\"message_code\":4},{\"message_type\":2,\"message_code\":5},{\"message_type\":2,\"message_code\":6},{\"message_type\":2,\"message_code\":7},{\"message_type\":2,\"message_code\":8},{\"message_type\":2,\"message_code\":9},{\"message_type\":2,\"message_code\":10},{\"message_type\":2,\"message_code\":11},{\"message_type\":2,\"message_code\":12},{\"message_type\":2,\"message_code\":13},{\"message_type\":162,\"message_code\":129},{\"message_type\":162,\"message_code\":130},{\"message_type\":162,\"message_code\":131},{\"message_type\":162,\"message_code\":132},{\"message_type\":162,\"message_code\":133},{\"message_type\":162,\"message_code\":134},{\"message_type\":162,\"message_code\":135},{\"message_type\":162,\"message_code\":136},{\"message_type\":162,\"message_code\":137}]}}]}",
        ],
        false,
    );
}

/// `get_device_messages_reply_empty` (tests/vectors/mscip/base.yaml:109)
#[test]
fn case_get_device_messages_reply_empty() {
    check(
        "a5a50106800203008300598d",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"device_messages\",\"values\":{\"messages\":[]}}]}",
        ],
        false,
    );
}

/// `mscip_device_reset_command` (tests/vectors/mscip/base.yaml:123)
#[test]
fn case_mscip_device_reset_command() {
    check(
        "a5a5010204005129",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"device_reset\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_device_reset_reply` (tests/vectors/mscip/base.yaml:133)
#[test]
fn case_mscip_device_reset_reply() {
    check(
        "a5a5010480020400d5d3",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":4,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `get_device_model_command` (tests/vectors/mscip/base.yaml:143)
#[test]
fn case_get_device_model_command() {
    check(
        "a5a501020500522b",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_device_model_reply` (tests/vectors/mscip/base.yaml:153)
#[test]
fn case_get_device_model_reply() {
    check(
        "a5a501168002050085102020202020204d535f494d5533303230ec54",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":5,\"error_code\":0}},{\"descriptor\":133,\"name\":\"device_model\",\"values\":{\"model\":\"      MS_IMU3020\"}}]}",
        ],
        false,
    );
}

/// `get_device_sn_command` (tests/vectors/mscip/base.yaml:166)
#[test]
fn case_get_device_sn_command() {
    check(
        "a5a501020600532d",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":6,\"name\":\"get_device_sn\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_device_sn_reply` (tests/vectors/mscip/base.yaml:176)
#[test]
fn case_get_device_sn_reply() {
    check(
        "a5a5011680020600861020202020202020202020203230323638e123",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":6,\"error_code\":0}},{\"descriptor\":134,\"name\":\"device_sn\",\"values\":{\"serial_number\":\"           20268\"}}]}",
        ],
        false,
    );
}

/// `get_device_sn_reply_published` (tests/vectors/mscip/base.yaml:192)
#[test]
fn case_get_device_sn_reply_published() {
    check(
        "a5a501168002060086102020202020202020202020203230323638e123",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5a501168002060086102020202020202020202020203230323638e123\"}",
        ],
        true,
    );
}

/// `get_device_fw_command` (tests/vectors/mscip/base.yaml:209)
#[test]
fn case_get_device_fw_command() {
    check(
        "a5a501020700542f",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":7,\"name\":\"get_device_fw\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_device_fw_reply` (tests/vectors/mscip/base.yaml:219)
#[test]
fn case_get_device_fw_reply() {
    check(
        "a5a50116800207008710202020202020202020525f315f325f33a625",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":7,\"error_code\":0}},{\"descriptor\":135,\"name\":\"device_fw\",\"values\":{\"firmware\":\"         R_1_2_3\"}}]}",
        ],
        false,
    );
}

/// `get_device_fw_reply_published` (tests/vectors/mscip/base.yaml:235)
#[test]
fn case_get_device_fw_reply_published() {
    check(
        "a5a501168002070087102020202020202020202020525f315f325f33a625",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5a501168002070087102020202020202020202020525f315f325f33a625\"}",
        ],
        true,
    );
}

/// `get_device_cal_command` (tests/vectors/mscip/base.yaml:250)
#[test]
fn case_get_device_cal_command() {
    check(
        "a5a5010208005531",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":8,\"name\":\"get_device_cal\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_device_cal_reply` (tests/vectors/mscip/base.yaml:260)
#[test]
fn case_get_device_cal_reply() {
    check(
        "a5a5011680020800881020202020202030352d30382d323031353210",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":8,\"error_code\":0}},{\"descriptor\":136,\"name\":\"device_cal\",\"values\":{\"date\":\"      05-08-2015\"}}]}",
        ],
        false,
    );
}

/// `get_device_cal_reply_published` (tests/vectors/mscip/base.yaml:276)
#[test]
fn case_get_device_cal_reply_published() {
    check(
        "a5a50116800208008810202020202030352d30382d323031353210",
        None,
        &["{\"offset\":0,\"skipped\":\"a5a50116800208008810202020202030352d30382d323031353210\"}"],
        true,
    );
}

/// `correlate_gps_time_command` (tests/vectors/mscip/base.yaml:291)
#[test]
fn case_correlate_gps_time_command() {
    check(
        "a5a501080906072f000002ff99af",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"correlate_gps_time\",\"values\":{\"week\":1839,\"seconds\":767}}]}",
        ],
        false,
    );
}

/// `correlate_gps_time_reply` (tests/vectors/mscip/base.yaml:304)
#[test]
fn case_correlate_gps_time_reply() {
    check(
        "a5a5010480020900dadd",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":9,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `mscip_nack_checksum_error` (tests/vectors/mscip/base.yaml:314)
#[test]
fn case_mscip_nack_checksum_error() {
    check(
        "a5a5010480020201d4d0",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":1}}]}",
        ],
        false,
    );
}

/// `mscip_nack_invalid_message_type` (tests/vectors/mscip/base.yaml:328)
#[test]
fn case_mscip_nack_invalid_message_type() {
    check(
        "a5a5030480020102d6db",
        None,
        &[
            "{\"offset\":0,\"set\":3,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":1,\"error_code\":2}}]}",
        ],
        false,
    );
}

/// `mscip_nack_invalid_message_code` (tests/vectors/mscip/base.yaml:344)
#[test]
fn case_mscip_nack_invalid_message_code() {
    check(
        "a5a5010480020a03dee2",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":10,\"error_code\":3}}]}",
        ],
        false,
    );
}

/// `mscip_nack_invalid_parameter` (tests/vectors/mscip/base.yaml:358)
#[test]
fn case_mscip_nack_invalid_parameter() {
    check(
        "a5a5020480020104d7d7",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":1,\"error_code\":4}}]}",
        ],
        false,
    );
}

/// `get_device_model_nack` (tests/vectors/mscip/base.yaml:372)
#[test]
fn case_get_device_model_nack() {
    check(
        "a5a5010480020501d7d6",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":5,\"error_code\":1}}]}",
        ],
        false,
    );
}

/// `correlate_gps_time_command_end_of_week` (tests/vectors/mscip/base.yaml:386)
#[test]
fn case_correlate_gps_time_command_end_of_week() {
    check(
        "a5a501080906096000093a7f8dbb",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"correlate_gps_time\",\"values\":{\"week\":2400,\"seconds\":604799}}]}",
        ],
        false,
    );
}

/// `encode_input_irregular_size_byte` (tests/vectors/mscip/encode_input.yaml:5)
#[test]
fn case_encode_input_irregular_size_byte() {
    check(
        "a5a502030500025688",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_write` (tests/vectors/mscip/imu_config.yaml:12)
#[test]
fn case_uart_baud_rate_write() {
    check(
        "a5a502070105010001c2001d84",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\",\"values\":{\"function\":1,\"baud_rate\":115200}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_write_reply` (tests/vectors/mscip/imu_config.yaml:22)
#[test]
fn case_uart_baud_rate_write_reply() {
    check(
        "a5a5020480020100d3d3",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":1,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_read` (tests/vectors/mscip/imu_config.yaml:32)
#[test]
fn case_uart_baud_rate_read() {
    check(
        "a5a50203010102537e",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_save` (tests/vectors/mscip/imu_config.yaml:46)
#[test]
fn case_uart_baud_rate_save() {
    check(
        "a5a50203010103547f",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_load` (tests/vectors/mscip/imu_config.yaml:60)
#[test]
fn case_uart_baud_rate_load() {
    check(
        "a5a502030101045580",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_default` (tests/vectors/mscip/imu_config.yaml:74)
#[test]
fn case_uart_baud_rate_default() {
    check(
        "a5a502030101055681",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_read_reply` (tests/vectors/mscip/imu_config.yaml:88)
#[test]
fn case_uart_baud_rate_read_reply() {
    check(
        "a5a5020a8002010081040001c20021a8",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":1,\"error_code\":0}},{\"descriptor\":129,\"name\":\"uart_baud_rate_response\",\"values\":{\"baud_rate\":115200}}]}",
        ],
        false,
    );
}

/// `uart_baud_rate_write_921600` (tests/vectors/mscip/imu_config.yaml:106)
#[test]
fn case_uart_baud_rate_write_921600() {
    check(
        "a5a50207010501000e10007847",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\",\"values\":{\"function\":1,\"baud_rate\":921600}}]}",
        ],
        false,
    );
}

/// `filter_write` (tests/vectors/mscip/imu_config.yaml:121)
#[test]
fn case_filter_write() {
    check(
        "a5a502040302010258e1",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{\"function\":1,\"bandwidth\":2}}]}",
        ],
        false,
    );
}

/// `filter_write_reply` (tests/vectors/mscip/imu_config.yaml:131)
#[test]
fn case_filter_write_reply() {
    check(
        "a5a5020480020300d5d7",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":3,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `filter_read` (tests/vectors/mscip/imu_config.yaml:141)
#[test]
fn case_filter_read() {
    check(
        "a5a502030301025584",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `filter_save` (tests/vectors/mscip/imu_config.yaml:155)
#[test]
fn case_filter_save() {
    check(
        "a5a502030301035685",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `filter_load` (tests/vectors/mscip/imu_config.yaml:169)
#[test]
fn case_filter_load() {
    check(
        "a5a502030301045786",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `filter_default` (tests/vectors/mscip/imu_config.yaml:183)
#[test]
fn case_filter_default() {
    check(
        "a5a502030301055887",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `filter_read_reply` (tests/vectors/mscip/imu_config.yaml:197)
#[test]
fn case_filter_read_reply() {
    check(
        "a5a50207800203008301025efb",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"filter_response\",\"values\":{\"bandwidth\":2}}]}",
        ],
        false,
    );
}

/// `filter_write_disabled` (tests/vectors/mscip/imu_config.yaml:215)
#[test]
fn case_filter_write_disabled() {
    check(
        "a5a502040302010056df",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{\"function\":1,\"bandwidth\":0}}]}",
        ],
        false,
    );
}

/// `filter_save_with_placeholder` (tests/vectors/mscip/imu_config.yaml:227)
#[test]
fn case_filter_save_with_placeholder() {
    check(
        "a5a50204030203075fea",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{\"function\":3,\"bandwidth\":7}}]}",
        ],
        false,
    );
}

/// `sample_rate_write` (tests/vectors/mscip/imu_config.yaml:242)
#[test]
fn case_sample_rate_write() {
    check(
        "a5a5020504030100126b56",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{\"function\":1,\"decimation\":18}}]}",
        ],
        false,
    );
}

/// `sample_rate_write_reply` (tests/vectors/mscip/imu_config.yaml:254)
#[test]
fn case_sample_rate_write_reply() {
    check(
        "a5a5020480020400d6d9",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":4,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `sample_rate_read` (tests/vectors/mscip/imu_config.yaml:264)
#[test]
fn case_sample_rate_read() {
    check(
        "a5a502030401025687",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `sample_rate_save` (tests/vectors/mscip/imu_config.yaml:278)
#[test]
fn case_sample_rate_save() {
    check(
        "a5a502030401035788",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `sample_rate_load` (tests/vectors/mscip/imu_config.yaml:292)
#[test]
fn case_sample_rate_load() {
    check(
        "a5a502030401045889",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `sample_rate_default` (tests/vectors/mscip/imu_config.yaml:306)
#[test]
fn case_sample_rate_default() {
    check(
        "a5a50203040105598a",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `sample_rate_read_reply` (tests/vectors/mscip/imu_config.yaml:320)
#[test]
fn case_sample_rate_read_reply() {
    check(
        "a5a5020880020400840200086873",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":4,\"error_code\":0}},{\"descriptor\":132,\"name\":\"sample_rate_response\",\"values\":{\"decimation\":8}}]}",
        ],
        false,
    );
}

/// `sample_rate_write_100hz` (tests/vectors/mscip/imu_config.yaml:338)
#[test]
fn case_sample_rate_write_100hz() {
    check(
        "a5a502050403010008614c",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{\"function\":1,\"decimation\":8}}]}",
        ],
        false,
    );
}

/// `select_sensors_write` (tests/vectors/mscip/imu_config.yaml:352)
#[test]
fn case_select_sensors_write() {
    check(
        "a5a502060503010081825e2e",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\",\"values\":{\"function\":1,\"reserved\":0,\"sensors\":[129,130]}}]}",
        ],
        false,
    );
}

/// `select_sensors_write_reply` (tests/vectors/mscip/imu_config.yaml:367)
#[test]
fn case_select_sensors_write_reply() {
    check(
        "a5a5020480020500d7db",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":5,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `select_sensors_read` (tests/vectors/mscip/imu_config.yaml:377)
#[test]
fn case_select_sensors_read() {
    check(
        "a5a502030500025688",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `select_sensors_save` (tests/vectors/mscip/imu_config.yaml:392)
#[test]
fn case_select_sensors_save() {
    check(
        "a5a502030500035789",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `select_sensors_load` (tests/vectors/mscip/imu_config.yaml:407)
#[test]
fn case_select_sensors_load() {
    check(
        "a5a50203050004588a",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `select_sensors_default` (tests/vectors/mscip/imu_config.yaml:422)
#[test]
fn case_select_sensors_default() {
    check(
        "a5a50203050005598b",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `select_sensors_read_reply` (tests/vectors/mscip/imu_config.yaml:437)
#[test]
fn case_select_sensors_read_reply() {
    check(
        "a5a50208800205008502818265f9",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":5,\"error_code\":0}},{\"descriptor\":133,\"name\":\"select_sensors_response\",\"values\":{\"sensors\":[129,130]}}]}",
        ],
        false,
    );
}

/// `select_sensors_write_several` (tests/vectors/mscip/imu_config.yaml:457)
#[test]
fn case_select_sensors_write_several() {
    check(
        "a5a5020a050701008182868788847f37",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\",\"values\":{\"function\":1,\"reserved\":0,\"sensors\":[129,130,134,135,136,132]}}]}",
        ],
        false,
    );
}

/// `get_internal_sample_rate_command` (tests/vectors/mscip/imu_config.yaml:473)
#[test]
fn case_get_internal_sample_rate_command() {
    check(
        "a5a5020206005431",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":6,\"name\":\"get_internal_sample_rate\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_internal_sample_rate_reply` (tests/vectors/mscip/imu_config.yaml:483)
#[test]
fn case_get_internal_sample_rate_reply() {
    check(
        "a5a50208800206008602032087a5",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":6,\"error_code\":0}},{\"descriptor\":134,\"name\":\"internal_sample_rate\",\"values\":{\"rate\":800}}]}",
        ],
        false,
    );
}

/// `get_internal_sample_rate_reply_1000hz` (tests/vectors/mscip/imu_config.yaml:494)
#[test]
fn case_get_internal_sample_rate_reply_1000hz() {
    check(
        "a5a5020880020600860203e84f6d",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":6,\"error_code\":0}},{\"descriptor\":134,\"name\":\"internal_sample_rate\",\"values\":{\"rate\":1000}}]}",
        ],
        false,
    );
}

/// `accel_range_write` (tests/vectors/mscip/imu_config.yaml:509)
#[test]
fn case_accel_range_write() {
    check(
        "a5a50204070201025cf1",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{\"function\":1,\"range\":2}}]}",
        ],
        false,
    );
}

/// `accel_range_write_reply` (tests/vectors/mscip/imu_config.yaml:523)
#[test]
fn case_accel_range_write_reply() {
    check(
        "a5a5020480020700d9df",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":7,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `accel_range_read` (tests/vectors/mscip/imu_config.yaml:533)
#[test]
fn case_accel_range_read() {
    check(
        "a5a502030701025990",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `accel_range_save` (tests/vectors/mscip/imu_config.yaml:547)
#[test]
fn case_accel_range_save() {
    check(
        "a5a502030701035a91",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `accel_range_load` (tests/vectors/mscip/imu_config.yaml:561)
#[test]
fn case_accel_range_load() {
    check(
        "a5a502030701045b92",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `accel_range_default` (tests/vectors/mscip/imu_config.yaml:575)
#[test]
fn case_accel_range_default() {
    check(
        "a5a502030701055c93",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `accel_range_read_reply` (tests/vectors/mscip/imu_config.yaml:589)
#[test]
fn case_accel_range_read_reply() {
    check(
        "a5a5020780020700870102661b",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":7,\"error_code\":0}},{\"descriptor\":135,\"name\":\"accel_range_response\",\"values\":{\"range\":2}}]}",
        ],
        false,
    );
}

/// `gyro_range_write` (tests/vectors/mscip/imu_config.yaml:607)
#[test]
fn case_gyro_range_write() {
    check(
        "a5a50204080201025df5",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{\"function\":1,\"range\":2}}]}",
        ],
        false,
    );
}

/// `gyro_range_write_reply` (tests/vectors/mscip/imu_config.yaml:617)
#[test]
fn case_gyro_range_write_reply() {
    check(
        "a5a5020480020800dae1",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":8,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `gyro_range_read` (tests/vectors/mscip/imu_config.yaml:627)
#[test]
fn case_gyro_range_read() {
    check(
        "a5a502030801025a93",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `gyro_range_save` (tests/vectors/mscip/imu_config.yaml:641)
#[test]
fn case_gyro_range_save() {
    check(
        "a5a502030801035b94",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `gyro_range_load` (tests/vectors/mscip/imu_config.yaml:655)
#[test]
fn case_gyro_range_load() {
    check(
        "a5a502030801045c95",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `gyro_range_default` (tests/vectors/mscip/imu_config.yaml:669)
#[test]
fn case_gyro_range_default() {
    check(
        "a5a502030801055d96",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `gyro_range_read_reply` (tests/vectors/mscip/imu_config.yaml:683)
#[test]
fn case_gyro_range_read_reply() {
    check(
        "a5a50207800208008801026823",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":8,\"error_code\":0}},{\"descriptor\":136,\"name\":\"gyro_range_response\",\"values\":{\"range\":2}}]}",
        ],
        false,
    );
}

/// `config_all_save` (tests/vectors/mscip/imu_config.yaml:701)
#[test]
fn case_config_all_save() {
    check(
        "a5a502030901035c97",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":9,\"name\":\"config_all\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `config_all_reply` (tests/vectors/mscip/imu_config.yaml:711)
#[test]
fn case_config_all_reply() {
    check(
        "a5a5020480020900dbe3",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":9,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `config_all_load` (tests/vectors/mscip/imu_config.yaml:721)
#[test]
fn case_config_all_load() {
    check(
        "a5a502030901045d98",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":9,\"name\":\"config_all\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `config_all_default` (tests/vectors/mscip/imu_config.yaml:734)
#[test]
fn case_config_all_default() {
    check(
        "a5a502030901055e99",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":9,\"name\":\"config_all\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `data_on_off_write` (tests/vectors/mscip/imu_config.yaml:748)
#[test]
fn case_data_on_off_write() {
    check(
        "a5a502040a0201015efc",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":{\"function\":1,\"control\":1}}]}",
        ],
        false,
    );
}

/// `data_on_off_write_reply` (tests/vectors/mscip/imu_config.yaml:758)
#[test]
fn case_data_on_off_write_reply() {
    check(
        "a5a5020480020a00dce5",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":10,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `data_on_off_read` (tests/vectors/mscip/imu_config.yaml:768)
#[test]
fn case_data_on_off_read() {
    check(
        "a5a502030a01025c99",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `data_on_off_save` (tests/vectors/mscip/imu_config.yaml:782)
#[test]
fn case_data_on_off_save() {
    check(
        "a5a502030a01035d9a",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `data_on_off_load` (tests/vectors/mscip/imu_config.yaml:796)
#[test]
fn case_data_on_off_load() {
    check(
        "a5a502030a01045e9b",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `data_on_off_default` (tests/vectors/mscip/imu_config.yaml:810)
#[test]
fn case_data_on_off_default() {
    check(
        "a5a502030a01055f9c",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `data_on_off_read_reply` (tests/vectors/mscip/imu_config.yaml:824)
#[test]
fn case_data_on_off_read_reply() {
    check(
        "a5a5020780020a008a01016b32",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":10,\"error_code\":0}},{\"descriptor\":138,\"name\":\"data_on_off_response\",\"values\":{\"control\":1}}]}",
        ],
        false,
    );
}

/// `data_on_off_write_off` (tests/vectors/mscip/imu_config.yaml:841)
#[test]
fn case_data_on_off_write_off() {
    check(
        "a5a502040a0201005dfb",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":{\"function\":1,\"control\":0}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_write` (tests/vectors/mscip/imu_config.yaml:854)
#[test]
fn case_xtrig_on_off_write() {
    check(
        "a5a502040b0201015f00",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\",\"values\":{\"function\":1,\"control\":1}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_write_reply` (tests/vectors/mscip/imu_config.yaml:864)
#[test]
fn case_xtrig_on_off_write_reply() {
    check(
        "a5a5020480020b00dde7",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":11,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_read` (tests/vectors/mscip/imu_config.yaml:874)
#[test]
fn case_xtrig_on_off_read() {
    check(
        "a5a502030b01025d9c",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_save` (tests/vectors/mscip/imu_config.yaml:888)
#[test]
fn case_xtrig_on_off_save() {
    check(
        "a5a502030b01035e9d",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_load` (tests/vectors/mscip/imu_config.yaml:902)
#[test]
fn case_xtrig_on_off_load() {
    check(
        "a5a502030b01045f9e",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_default` (tests/vectors/mscip/imu_config.yaml:916)
#[test]
fn case_xtrig_on_off_default() {
    check(
        "a5a502030b0105609f",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_read_reply` (tests/vectors/mscip/imu_config.yaml:930)
#[test]
fn case_xtrig_on_off_read_reply() {
    check(
        "a5a5020780020b008b01006c39",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":11,\"error_code\":0}},{\"descriptor\":139,\"name\":\"xtrig_on_off_response\",\"values\":{\"control\":0}}]}",
        ],
        false,
    );
}

/// `xtrig_on_off_write_off` (tests/vectors/mscip/imu_config.yaml:948)
#[test]
fn case_xtrig_on_off_write_off() {
    check(
        "a5a502040b0201005eff",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\",\"values\":{\"function\":1,\"control\":0}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_write` (tests/vectors/mscip/imu_config.yaml:961)
#[test]
fn case_select_sensors_rev_b_write() {
    check(
        "a5a502050c0301818264f0",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":{\"function\":1,\"sensors\":[129,130]}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_write_reply` (tests/vectors/mscip/imu_config.yaml:971)
#[test]
fn case_select_sensors_rev_b_write_reply() {
    check(
        "a5a5020480020c00dee9",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":12,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_read` (tests/vectors/mscip/imu_config.yaml:981)
#[test]
fn case_select_sensors_rev_b_read() {
    check(
        "a5a502030c01025e9f",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_save` (tests/vectors/mscip/imu_config.yaml:995)
#[test]
fn case_select_sensors_rev_b_save() {
    check(
        "a5a502030c01035fa0",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_load` (tests/vectors/mscip/imu_config.yaml:1009)
#[test]
fn case_select_sensors_rev_b_load() {
    check(
        "a5a502030c010460a1",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_default` (tests/vectors/mscip/imu_config.yaml:1023)
#[test]
fn case_select_sensors_rev_b_default() {
    check(
        "a5a502030c010561a2",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_read_reply` (tests/vectors/mscip/imu_config.yaml:1037)
#[test]
fn case_select_sensors_rev_b_read_reply() {
    check(
        "a5a5020980020c008c03818289fe49",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":12,\"error_code\":0}},{\"descriptor\":140,\"name\":\"select_sensors_rev_b_response\",\"values\":{\"sensors\":[129,130,137]}}]}",
        ],
        false,
    );
}

/// `select_sensors_rev_b_write_all` (tests/vectors/mscip/imu_config.yaml:1055)
#[test]
fn case_select_sensors_rev_b_write_all() {
    check(
        "a5a5020c0c0a018182838485868788891ce0",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":{\"function\":1,\"sensors\":[129,130,131,132,133,134,135,136,137]}}]}",
        ],
        false,
    );
}

/// `aux_accel_range_write` (tests/vectors/mscip/imu_config.yaml:1069)
#[test]
fn case_aux_accel_range_write() {
    check(
        "a5a502040d020105650c",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\",\"values\":{\"function\":1,\"range\":5}}]}",
        ],
        false,
    );
}

/// `aux_accel_range_write_reply` (tests/vectors/mscip/imu_config.yaml:1083)
#[test]
fn case_aux_accel_range_write_reply() {
    check(
        "a5a5020480020d00dfeb",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":13,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `aux_accel_range_read` (tests/vectors/mscip/imu_config.yaml:1093)
#[test]
fn case_aux_accel_range_read() {
    check(
        "a5a502030d01025fa2",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `aux_accel_range_save` (tests/vectors/mscip/imu_config.yaml:1107)
#[test]
fn case_aux_accel_range_save() {
    check(
        "a5a502030d010360a3",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `aux_accel_range_load` (tests/vectors/mscip/imu_config.yaml:1121)
#[test]
fn case_aux_accel_range_load() {
    check(
        "a5a502030d010461a4",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `aux_accel_range_default` (tests/vectors/mscip/imu_config.yaml:1135)
#[test]
fn case_aux_accel_range_default() {
    check(
        "a5a502030d010562a5",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `aux_accel_range_read_reply` (tests/vectors/mscip/imu_config.yaml:1149)
#[test]
fn case_aux_accel_range_read_reply() {
    check(
        "a5a5020780020d008d0105754e",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":13,\"error_code\":0}},{\"descriptor\":141,\"name\":\"aux_accel_range_response\",\"values\":{\"range\":5}}]}",
        ],
        false,
    );
}

/// `imu_data_default` (tests/vectors/mscip/imu_data.yaml:11)
#[test]
fn case_imu_data_default() {
    check(
        "a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}",
        ],
        false,
    );
}

/// `scaled_accel` (tests/vectors/mscip/imu_data.yaml:26)
#[test]
fn case_scaled_accel() {
    check(
        "a5a5a20e810c37a7c5ac377ba8823f800065d61a",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}}]}",
        ],
        false,
    );
}

/// `scaled_gyro` (tests/vectors/mscip/imu_data.yaml:36)
#[test]
fn case_scaled_gyro() {
    check(
        "a5a5a20e820c37a7c5ac377ba8823749539c2240",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}",
        ],
        false,
    );
}

/// `scaled_mag` (tests/vectors/mscip/imu_data.yaml:46)
#[test]
fn case_scaled_mag() {
    check(
        "a5a5a20e830c37a7c5ac377ba8823749539c234e",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":131,\"name\":\"scaled_mag\",\"values\":{\"mag\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}",
        ],
        false,
    );
}

/// `delta_theta` (tests/vectors/mscip/imu_data.yaml:56)
#[test]
fn case_delta_theta() {
    check(
        "a5a5a20e840c37a7c5ac377ba8823749539c245c",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":132,\"name\":\"delta_theta\",\"values\":{\"delta_theta\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}",
        ],
        false,
    );
}

/// `delta_velocity` (tests/vectors/mscip/imu_data.yaml:66)
#[test]
fn case_delta_velocity() {
    check(
        "a5a5a20e850c37a7c5ac377ba8823749539c256a",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":133,\"name\":\"delta_velocity\",\"values\":{\"delta_velocity\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}",
        ],
        false,
    );
}

/// `scaled_aux_accel` (tests/vectors/mscip/imu_data.yaml:76)
#[test]
fn case_scaled_aux_accel() {
    check(
        "a5a5a20e890c37a7c5ac377ba8823f800065de8a",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":137,\"name\":\"scaled_aux_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}}]}",
        ],
        false,
    );
}

/// `scaled_pressure_published` (tests/vectors/mscip/imu_data.yaml:89)
#[test]
fn case_scaled_pressure_published() {
    check(
        "a5a5a2068604000003fd7cb4",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":134,\"name\":\"scaled_pressure\",\"values\":{\"pressure\":1.4307257320756382e-42}}]}",
        ],
        false,
    );
}

/// `scaled_pressure` (tests/vectors/mscip/imu_data.yaml:108)
#[test]
fn case_scaled_pressure() {
    check(
        "a5a5a2068604447f40007fbe",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":134,\"name\":\"scaled_pressure\",\"values\":{\"pressure\":1021.0}}]}",
        ],
        false,
    );
}

/// `scaled_temperature_published` (tests/vectors/mscip/imu_data.yaml:121)
#[test]
fn case_scaled_temperature_published() {
    check(
        "a5a5a20687040000001996d0",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":135,\"name\":\"scaled_temperature\",\"values\":{\"temperature\":3.5032461608120427e-44}}]}",
        ],
        false,
    );
}

/// `scaled_temperature` (tests/vectors/mscip/imu_data.yaml:140)
#[test]
fn case_scaled_temperature() {
    check(
        "a5a5a206870441c800008613",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":135,\"name\":\"scaled_temperature\",\"values\":{\"temperature\":25.0}}]}",
        ],
        false,
    );
}

/// `gps_correlated_time_published` (tests/vectors/mscip/imu_data.yaml:153)
#[test]
fn case_gps_correlated_time_published() {
    check(
        "a5a5a20e880c410944c000000000072f00081a32",
        None,
        &["{\"offset\":0,\"skipped\":\"a5a5a20e880c410944c000000000072f00081a32\"}"],
        true,
    );
}

/// `gps_correlated_time` (tests/vectors/mscip/imu_data.yaml:173)
#[test]
fn case_gps_correlated_time() {
    check(
        "a5a5a20e880c410944c000000000072f00081a15",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\",\"values\":{\"seconds\":207000.0,\"week\":1839,\"flags\":8}}]}",
        ],
        false,
    );
}

/// `gps_correlated_time_not_set` (tests/vectors/mscip/imu_data.yaml:187)
#[test]
fn case_gps_correlated_time_not_set() {
    check(
        "a5a5a20e880c4028b0a3d70a3d7100000004dc85",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\",\"values\":{\"seconds\":12.345,\"week\":0,\"flags\":4}}]}",
        ],
        false,
    );
}

/// `gps_correlated_time_set_and_pps` (tests/vectors/mscip/imu_data.yaml:202)
#[test]
fn case_gps_correlated_time_set_and_pps() {
    check(
        "a5a5a20e880c410944c00a3d70a4072f000370df",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\",\"values\":{\"seconds\":207000.005,\"week\":1839,\"flags\":3}}]}",
        ],
        false,
    );
}

/// `imu_data_gps_accel_temperature` (tests/vectors/mscip/imu_data.yaml:218)
#[test]
fn case_imu_data_gps_accel_temperature() {
    check(
        "a5a5a222880c410944c000000000072f0000810c00000000bf0000003f800000870441c80000c52b",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\",\"values\":{\"seconds\":207000.0,\"week\":1839,\"flags\":0}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[0.0,-0.5,1.0]}},{\"descriptor\":135,\"name\":\"scaled_temperature\",\"values\":{\"temperature\":25.0}}]}",
        ],
        false,
    );
}

/// `imu_data_all_fields` (tests/vectors/mscip/imu_data.yaml:235)
#[test]
fn case_imu_data_all_fields() {
    check(
        "a5a5a26e810c3c800000be8000003f800000820c3f000000bfc0000042b40000830c3e8000003d800000bf000000840c3a800000bb00000000000000850c3ba0000000000000bc2000008604447d50008704c2220000880c412274fffd70a3d709600001890cc0000000408000003e0000001011",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[0.015625,-0.25,1.0]}},{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":[0.5,-1.5,90.0]}},{\"descriptor\":131,\"name\":\"scaled_mag\",\"values\":{\"mag\":[0.25,0.0625,-0.5]}},{\"descriptor\":132,\"name\":\"delta_theta\",\"values\":{\"delta_theta\":[0.0009765625,-0.001953125,0.0]}},{\"descriptor\":133,\"name\":\"delta_velocity\",\"values\":{\"delta_velocity\":[0.0048828125,0.0,-0.009765625]}},{\"descriptor\":134,\"name\":\"scaled_pressure\",\"values\":{\"pressure\":1013.25}},{\"descriptor\":135,\"name\":\"scaled_temperature\",\"values\":{\"temperature\":-40.5}},{\"descriptor\":136,\"name\":\"gps_correlated_time\",\"values\":{\"seconds\":604799.995,\"week\":2400,\"flags\":1}},{\"descriptor\":137,\"name\":\"scaled_aux_accel\",\"values\":{\"accel\":[-2.0,4.0,0.125]}}]}",
        ],
        false,
    );
}

/// `mscip_garbage_around_packets` (tests/streams/mscip/framing_and_fields.yaml:8)
#[test]
fn stream_mscip_garbage_around_packets() {
    check(
        "00ff13a5a5010202004f2555a5a5010480020200d3cfa5",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"00ff13\"}",
            "{\"offset\":3,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":11,\"skipped\":\"55\"}",
            "{\"offset\":12,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}",
            "{\"offset\":22,\"skipped\":\"a5\"}",
        ],
        false,
    );
}

/// `mscip_false_sync_running_past_the_end` (tests/streams/mscip/framing_and_fields.yaml:28)
#[test]
fn stream_mscip_false_sync_running_past_the_end() {
    check(
        "a5a50130a5a5010202004f25",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5a50130\"}",
            "{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_false_sync_bad_checksum_packet_inside` (tests/streams/mscip/framing_and_fields.yaml:42)
#[test]
fn stream_mscip_false_sync_bad_checksum_packet_inside() {
    check(
        "a5a5010aa5a5010202004f2500000000",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5a5010a\"}",
            "{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":12,\"skipped\":\"00000000\"}",
        ],
        false,
    );
}

/// `mscip_extra_sync_byte` (tests/streams/mscip/framing_and_fields.yaml:58)
#[test]
fn stream_mscip_extra_sync_byte() {
    check(
        "a5a5a5010202004f25",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5\"}",
            "{\"offset\":1,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_packets_back_to_back` (tests/streams/mscip/framing_and_fields.yaml:72)
#[test]
fn stream_mscip_packets_back_to_back() {
    check(
        "a5a502050c0301818264f0a5a5020480020c00dee9a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":{\"function\":1,\"sensors\":[129,130]}}]}",
            "{\"offset\":11,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":12,\"error_code\":0}}]}",
            "{\"offset\":21,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}",
            "{\"offset\":55,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}",
        ],
        false,
    );
}

/// `mscip_mip_packet_in_mscip_stream` (tests/streams/mscip/framing_and_fields.yaml:98)
#[test]
fn stream_mscip_mip_packet_in_mscip_stream() {
    check(
        "a5a5010202004f25756501020201e0c6a5a5010480020200d3cf",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":8,\"skipped\":\"756501020201e0c6\"}",
            "{\"offset\":16,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `mscip_bad_checksum_then_valid` (tests/streams/mscip/framing_and_fields.yaml:116)
#[test]
fn stream_mscip_bad_checksum_then_valid() {
    check(
        "a5a5010480020200d3cea5a5010480020200d3cf",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5a5010480020200d3ce\"}",
            "{\"offset\":10,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}",
        ],
        false,
    );
}

/// `mscip_truncated_packet_at_end` (tests/streams/mscip/framing_and_fields.yaml:129)
#[test]
fn stream_mscip_truncated_packet_at_end() {
    check(
        "a5a50104800202",
        None,
        &["{\"offset\":0,\"skipped\":\"a5a50104800202\"}"],
        true,
    );
}

/// `mscip_field_header_cut_short` (tests/streams/mscip/framing_and_fields.yaml:135)
#[test]
fn stream_mscip_field_header_cut_short() {
    check(
        "a5a50103020080d0f8",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}},{\"trailing\":\"80\",\"error\":\"field header at payload offset 2 needs 2 bytes, 1 left\"}]}",
        ],
        false,
    );
}

/// `mscip_field_size_overruns_payload` (tests/streams/mscip/framing_and_fields.yaml:146)
#[test]
fn stream_mscip_field_size_overruns_payload() {
    check(
        "a5a5010480030200d4d2",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"trailing\":\"80030200\",\"error\":\"field length 3 at payload offset 0 overruns the payload (4 bytes left)\"}]}",
        ],
        false,
    );
}

/// `mscip_field_too_short_for_type` (tests/streams/mscip/framing_and_fields.yaml:157)
#[test]
fn stream_mscip_field_too_short_for_type() {
    check(
        "a5a5a2048602447f3bb0",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":134,\"data\":\"447f\",\"error\":\"pressure: needs 4 bytes at offset 0, 2 left\"}]}",
        ],
        false,
    );
}

/// `mscip_field_with_trailing_bytes` (tests/streams/mscip/framing_and_fields.yaml:167)
#[test]
fn stream_mscip_field_with_trailing_bytes() {
    check(
        "a5a50103020155a6cf",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"data\":\"55\",\"error\":\"1 unexpected bytes at offset 0\"}]}",
        ],
        false,
    );
}

/// `mscip_message_list_with_half_entry` (tests/streams/mscip/framing_and_fields.yaml:177)
#[test]
fn stream_mscip_message_list_with_half_entry() {
    check(
        "a5a501058303010201dabd",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":131,\"data\":\"010201\",\"error\":\"messages: 3 bytes left at offset 0, not a multiple of 2\"}]}",
        ],
        false,
    );
}

/// `mscip_unknown_message_code` (tests/streams/mscip/framing_and_fields.yaml:188)
#[test]
fn stream_mscip_unknown_message_code() {
    check(
        "a5a501020a005735",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":10,\"data\":\"\",\"error\":\"unknown descriptor\"}]}",
        ],
        false,
    );
}

/// `mscip_ack_code_in_data_message` (tests/streams/mscip/framing_and_fields.yaml:199)
#[test]
fn stream_mscip_ack_code_in_data_message() {
    check(
        "a5a5a204800202007495",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":128,\"data\":\"0200\",\"error\":\"unknown descriptor\"}]}",
        ],
        false,
    );
}

/// `mscip_unknown_message_type` (tests/streams/mscip/framing_and_fields.yaml:210)
#[test]
fn stream_mscip_unknown_message_type() {
    check(
        "a5a5a30681043f8000003717",
        None,
        &[
            "{\"offset\":0,\"set\":163,\"fields\":[{\"descriptor\":129,\"data\":\"3f800000\",\"error\":\"unknown descriptor set\"}]}",
        ],
        false,
    );
}

/// `mscip_select_sensors_rev_a_with_a_regular_size_byte` (tests/streams/mscip/framing_and_fields.yaml:220)
#[test]
fn stream_mscip_select_sensors_rev_a_with_a_regular_size_byte() {
    check(
        "a5a502060504010081825f33",
        None,
        &[
            "{\"offset\":0,\"set\":2,\"fields\":[{\"trailing\":\"050401008182\",\"error\":\"field length 4 at payload offset 0 overruns the payload (6 bytes left)\"}]}",
        ],
        false,
    );
}

/// `mscip_empty_stream` (tests/streams/mscip/framing_and_fields_more.yaml:7)
#[test]
fn stream_mscip_empty_stream() {
    check("", None, &[], false);
}

/// `mscip_garbage_inside_packet` (tests/streams/mscip/framing_and_fields_more.yaml:11)
#[test]
fn stream_mscip_garbage_inside_packet() {
    check(
        "a5a50102aabbcc02004f25a5a5010202004f25",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5a50102aabbcc02004f25\"}",
            "{\"offset\":11,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_sync_bytes_inside_a_valid_payload` (tests/streams/mscip/framing_and_fields_more.yaml:26)
#[test]
fn stream_mscip_sync_bytes_inside_a_valid_payload() {
    check(
        "a5a5a2067e04a5a5a5a508f3a5a5010202004f25",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":126,\"data\":\"a5a5a5a5\",\"error\":\"unknown descriptor\"}]}",
            "{\"offset\":12,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_false_sync_of_maximum_length` (tests/streams/mscip/framing_and_fields_more.yaml:42)
#[test]
fn stream_mscip_false_sync_of_maximum_length() {
    check(
        "a5a5a2ffa5a5010202004f25a5a5010202004f25",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"a5a5a2ff\"}",
            "{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":12,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_longest_legal_packet` (tests/streams/mscip/framing_and_fields_more.yaml:59)
#[test]
fn stream_mscip_longest_legal_packet() {
    check(
        "a5a5a2ff810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf000000400000007e0100b03fa5a5010202004f25",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":126,\"data\":\"00\",\"error\":\"unknown descriptor\"}]}",
            "{\"offset\":261,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `mscip_empty_payloads` (tests/streams/mscip/framing_and_fields_more.yaml:103)
#[test]
fn stream_mscip_empty_payloads() {
    check(
        "a5a5a200ecc7a5a501004b85",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[]}",
            "{\"offset\":6,\"set\":1,\"fields\":[]}",
        ],
        false,
    );
}

/// `mscip_zero_length_fields` (tests/streams/mscip/framing_and_fields_more.yaml:112)
#[test]
fn stream_mscip_zero_length_fields() {
    check(
        "a5a5a21281007e00810c3f800000bf0000004000000048bd",
        None,
        &[
            "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"data\":\"\",\"error\":\"accel[0]: needs 4 bytes at offset 0, 0 left\"},{\"descriptor\":126,\"data\":\"\",\"error\":\"unknown descriptor\"},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}}]}",
        ],
        false,
    );
}

/// `mscip_unknown_command_set` (tests/streams/mscip/framing_and_fields_more.yaml:125)
#[test]
fn stream_mscip_unknown_command_set() {
    check(
        "a5a555020200a375",
        None,
        &[
            "{\"offset\":0,\"set\":85,\"fields\":[{\"descriptor\":2,\"data\":\"\",\"error\":\"unknown descriptor set\"}]}",
        ],
        false,
    );
}
