//! Golden vectors (tests/vectors/mip/) and stream corpus (tests/streams/mip/):
//! each case's bytes decode (whole, and fed in chunks of every size) to exactly the expected
//! canonical JSON lines, and those lines encode back to the bytes.

use mipcodec::fields::{FieldItem, Packet};
use mipcodec::parser::{Event, Parser};
use mipcodec::text::{decode_bytes, encode_text};
use mipcodec::{decode_field, decode_packet, AnyPacket, Device, LayoutCache};

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
fn json_of(value: &mipcodec::FieldValue) -> String {
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

/// `startup_settings_save_gx5` (tests/vectors/mip/3dm_config.yaml:13)
#[test]
fn case_startup_settings_save_gx5() {
    check(
        "75650c030330031f45",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\",\"device\":\"gx5_45\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `startup_settings_ack` (tests/vectors/mip/3dm_config.yaml:24)
#[test]
fn case_startup_settings_ack() {
    check(
        "75650c0404f130000f0a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":48,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `startup_settings_read_gx5` (tests/vectors/mip/3dm_config.yaml:33)
#[test]
fn case_startup_settings_read_gx5() {
    check(
        "75650c030330021e44",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\",\"device\":\"gx5_45\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `startup_settings_load_cv7` (tests/vectors/mip/3dm_config.yaml:47)
#[test]
fn case_startup_settings_load_cv7() {
    check(
        "75650c030330042046",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\",\"device\":\"cv7_ins\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `startup_settings_default_cv7` (tests/vectors/mip/3dm_config.yaml:60)
#[test]
fn case_startup_settings_default_cv7() {
    check(
        "75650c030330052147",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\",\"device\":\"cv7_ins\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_euler_example_2` (tests/vectors/mip/3dm_config.yaml:76)
#[test]
fn case_sensor_to_vehicle_euler_example_2() {
    check(
        "75650c0f0f3101bfc90ff90000000000000000c60f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":1,\"roll\":-1.5707999467849731,\"pitch\":0.0,\"yaw\":0.0}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_euler_example_3` (tests/vectors/mip/3dm_config.yaml:96)
#[test]
fn case_sensor_to_vehicle_euler_example_3() {
    check(
        "75650c0f0f3101000000003fc90ff93fc90ff9563d",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":1,\"roll\":0.0,\"pitch\":1.5707999467849731,\"yaw\":1.5707999467849731}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_euler_read` (tests/vectors/mip/3dm_config.yaml:116)
#[test]
fn case_sensor_to_vehicle_euler_read() {
    check(
        "75650c030331021f46",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_euler_reply` (tests/vectors/mip/3dm_config.yaml:128)
#[test]
fn case_sensor_to_vehicle_euler_reply() {
    check(
        "75650c1204f131000eb1000000003fc90ff93fc90ff9fdd3",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":49,\"ack_code\":0}},{\"descriptor\":177,\"name\":\"sensor_to_vehicle_euler_response\",\"values\":{\"roll\":0.0,\"pitch\":1.5707999467849731,\"yaw\":1.5707999467849731}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_quaternion_write_identity` (tests/vectors/mip/3dm_config.yaml:148)
#[test]
fn case_sensor_to_vehicle_quaternion_write_identity() {
    check(
        "75650c131332013f800000000000000000000000000000fe17",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":50,\"name\":\"sensor_to_vehicle_quaternion\",\"values\":{\"function\":1,\"q\":[1.0,0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_quaternion_reply` (tests/vectors/mip/3dm_config.yaml:161)
#[test]
fn case_sensor_to_vehicle_quaternion_reply() {
    check(
        "75650c1604f1320012b23f0000003f0000003f0000003f000000e3cc",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":50,\"ack_code\":0}},{\"descriptor\":178,\"name\":\"sensor_to_vehicle_quaternion_response\",\"values\":{\"q\":[0.5,0.5,0.5,0.5]}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_dcm_example_2` (tests/vectors/mip/3dm_config.yaml:175)
#[test]
fn case_sensor_to_vehicle_dcm_example_2() {
    check(
        "75650c272733013f800000000000000000000000000000000000003f80000000000000bf800000000000002529",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":51,\"name\":\"sensor_to_vehicle_dcm\",\"values\":{\"function\":1,\"dcm\":[1.0,0.0,0.0,0.0,0.0,1.0,0.0,-1.0,0.0]}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_dcm_example_3` (tests/vectors/mip/3dm_config.yaml:193)
#[test]
fn case_sensor_to_vehicle_dcm_example_3() {
    check(
        "75650c2727330100000000bf8000000000000000000000000000003f800000bf8000000000000000000000a529",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":51,\"name\":\"sensor_to_vehicle_dcm\",\"values\":{\"function\":1,\"dcm\":[0.0,-1.0,0.0,0.0,0.0,1.0,-1.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_dcm_reply` (tests/vectors/mip/3dm_config.yaml:210)
#[test]
fn case_sensor_to_vehicle_dcm_reply() {
    check(
        "75650c2a04f1330026b33f800000000000000000000000000000000000003f80000000000000bf80000000000000cee5",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":51,\"ack_code\":0}},{\"descriptor\":179,\"name\":\"sensor_to_vehicle_dcm_response\",\"values\":{\"dcm\":[1.0,0.0,0.0,0.0,0.0,1.0,0.0,-1.0,0.0]}}]}",
        ],
        false,
    );
}

/// `accel_bias_write_zero_gx5` (tests/vectors/mip/3dm_config.yaml:229)
#[test]
fn case_accel_bias_write_zero_gx5() {
    check(
        "75650c0f0f37010000000000000000000000003c75",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":55,\"name\":\"accel_bias\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"bias\":[0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `accel_bias_ack` (tests/vectors/mip/3dm_config.yaml:240)
#[test]
fn case_accel_bias_ack() {
    check(
        "75650c0404f137001618",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":55,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `accel_bias_write_no_ack_gx5` (tests/vectors/mip/3dm_config.yaml:249)
#[test]
fn case_accel_bias_write_no_ack_gx5() {
    check(
        "75650c0f0f37063b03126fba83126f00000000be32",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":55,\"name\":\"accel_bias\",\"device\":\"gx5_45\",\"values\":{\"function\":6,\"bias\":[0.0020000000949949026,-0.0010000000474974513,0.0]}}]}",
        ],
        false,
    );
}

/// `accel_bias_read_full_length_gx5` (tests/vectors/mip/3dm_config.yaml:264)
#[test]
fn case_accel_bias_read_full_length_gx5() {
    check(
        "75650c0f0f37020000000000000000000000003d82",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":55,\"name\":\"accel_bias\",\"device\":\"gx5_45\",\"values\":{\"function\":2,\"bias\":[0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `accel_bias_write_cv7` (tests/vectors/mip/3dm_config.yaml:280)
#[test]
fn case_accel_bias_write_cv7() {
    check(
        "75650c0f0f37013e800000be0000003d8000007541",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":55,\"name\":\"accel_bias\",\"device\":\"cv7_ins\",\"values\":{\"function\":1,\"bias\":[0.25,-0.125,0.0625]}}]}",
        ],
        false,
    );
}

/// `accel_bias_read_cv7` (tests/vectors/mip/3dm_config.yaml:294)
#[test]
fn case_accel_bias_read_cv7() {
    check(
        "75650c030337022552",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":55,\"name\":\"accel_bias\",\"device\":\"cv7_ins\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `accel_bias_reply` (tests/vectors/mip/3dm_config.yaml:307)
#[test]
fn case_accel_bias_reply() {
    check(
        "75650c1204f137000e9a3e800000be0000003d80000005b8",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":55,\"ack_code\":0}},{\"descriptor\":154,\"name\":\"accel_bias_response\",\"values\":{\"bias\":[0.25,-0.125,0.0625]}}]}",
        ],
        false,
    );
}

/// `gyro_bias_write_zero_gx5` (tests/vectors/mip/3dm_config.yaml:325)
#[test]
fn case_gyro_bias_write_zero_gx5() {
    check(
        "75650c0f0f38010000000000000000000000003d83",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":56,\"name\":\"gyro_bias\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"bias\":[0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `gyro_bias_ack` (tests/vectors/mip/3dm_config.yaml:336)
#[test]
fn case_gyro_bias_ack() {
    check(
        "75650c0404f13800171a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":56,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gyro_bias_save_cv7` (tests/vectors/mip/3dm_config.yaml:345)
#[test]
fn case_gyro_bias_save_cv7() {
    check(
        "75650c030338032755",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":56,\"name\":\"gyro_bias\",\"device\":\"cv7_ins\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `gyro_bias_write_cv7` (tests/vectors/mip/3dm_config.yaml:359)
#[test]
fn case_gyro_bias_write_cv7() {
    check(
        "75650c0f0f38013b03126fba83126f3a03126f7883",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":56,\"name\":\"gyro_bias\",\"device\":\"cv7_ins\",\"values\":{\"function\":1,\"bias\":[0.0020000000949949026,-0.0010000000474974513,0.0005000000237487257]}}]}",
        ],
        false,
    );
}

/// `gyro_bias_reply` (tests/vectors/mip/3dm_config.yaml:373)
#[test]
fn case_gyro_bias_reply() {
    check(
        "75650c1204f138000e9b3b03126fba83126f3a03126f0909",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":56,\"ack_code\":0}},{\"descriptor\":155,\"name\":\"gyro_bias_response\",\"values\":{\"bias\":[0.0020000000949949026,-0.0010000000474974513,0.0005000000237487257]}}]}",
        ],
        false,
    );
}

/// `capture_gyro_bias_command` (tests/vectors/mip/3dm_config.yaml:389)
#[test]
fn case_capture_gyro_bias_command() {
    check(
        "75650c04043927105ee0",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":57,\"name\":\"capture_gyro_bias\",\"values\":{\"averaging_time_ms\":10000}}]}",
        ],
        false,
    );
}

/// `capture_gyro_bias_reply` (tests/vectors/mip/3dm_config.yaml:399)
#[test]
fn case_capture_gyro_bias_reply() {
    check(
        "75650c1204f139000e9b000000000000000000000000cf19",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":57,\"ack_code\":0}},{\"descriptor\":155,\"name\":\"gyro_bias_response\",\"values\":{\"bias\":[0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `capture_gyro_bias_short_cv7` (tests/vectors/mip/3dm_config.yaml:416)
#[test]
fn case_capture_gyro_bias_short_cv7() {
    check(
        "75650c04043903e81270",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":57,\"name\":\"capture_gyro_bias\",\"values\":{\"averaging_time_ms\":1000}}]}",
        ],
        false,
    );
}

/// `mag_hard_iron_write_zero_gx5` (tests/vectors/mip/3dm_config.yaml:430)
#[test]
fn case_mag_hard_iron_write_zero_gx5() {
    check(
        "75650c0f0f3a010000000000000000000000003f9f",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":58,\"name\":\"mag_hard_iron_offset\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"offset\":[0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `mag_hard_iron_ack` (tests/vectors/mip/3dm_config.yaml:441)
#[test]
fn case_mag_hard_iron_ack() {
    check(
        "75650c0404f13a00191e",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":58,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `mag_hard_iron_write_cv7` (tests/vectors/mip/3dm_config.yaml:450)
#[test]
fn case_mag_hard_iron_write_cv7() {
    check(
        "75650c0f0f3a013da3d70abdf5c28f3eb333335ad8",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":58,\"name\":\"mag_hard_iron_offset\",\"device\":\"cv7_ins\",\"values\":{\"function\":1,\"offset\":[0.07999999821186066,-0.11999999731779099,0.3499999940395355]}}]}",
        ],
        false,
    );
}

/// `mag_hard_iron_reply` (tests/vectors/mip/3dm_config.yaml:464)
#[test]
fn case_mag_hard_iron_reply() {
    check(
        "75650c1204f13a000e9c3da3d70abdf5c28f3eb33333ec6f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":58,\"ack_code\":0}},{\"descriptor\":156,\"name\":\"mag_hard_iron_offset_response\",\"values\":{\"offset\":[0.07999999821186066,-0.11999999731779099,0.3499999940395355]}}]}",
        ],
        false,
    );
}

/// `mag_soft_iron_write_identity_gx5` (tests/vectors/mip/3dm_config.yaml:480)
#[test]
fn case_mag_soft_iron_write_identity_gx5() {
    check(
        "75650c27273b013f8000000000000000000000000000003f8000000000000000000000000000003f800000ad59",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":59,\"name\":\"mag_soft_iron_matrix\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"matrix\":[1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0]}}]}",
        ],
        false,
    );
}

/// `mag_soft_iron_ack` (tests/vectors/mip/3dm_config.yaml:498)
#[test]
fn case_mag_soft_iron_ack() {
    check(
        "75650c0404f13b001a20",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":59,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `mag_soft_iron_default_cv7` (tests/vectors/mip/3dm_config.yaml:512)
#[test]
fn case_mag_soft_iron_default_cv7() {
    check(
        "75650c03033b052c5d",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":59,\"name\":\"mag_soft_iron_matrix\",\"device\":\"cv7_ins\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `mag_soft_iron_reply` (tests/vectors/mip/3dm_config.yaml:526)
#[test]
fn case_mag_soft_iron_reply() {
    check(
        "75650c2a04f13b00269d3f828f5c3c23d70abcf5c28f3c23d70a3f7ae1483ca3d70abcf5c28f3ca3d70a3f8000005487",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":59,\"ack_code\":0}},{\"descriptor\":157,\"name\":\"mag_soft_iron_matrix_response\",\"values\":{\"matrix\":[1.0199999809265137,0.009999999776482582,-0.029999999329447746,0.009999999776482582,0.9800000190734863,0.019999999552965164,-0.029999999329447746,0.019999999552965164,1.0]}}]}",
        ],
        false,
    );
}

/// `coning_sculling_enable_write` (tests/vectors/mip/3dm_config.yaml:548)
#[test]
fn case_coning_sculling_enable_write() {
    check(
        "75650c04043e01012e94",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":62,\"name\":\"coning_sculling_enable\",\"values\":{\"function\":1,\"enable\":true}}]}",
        ],
        false,
    );
}

/// `coning_sculling_enable_ack` (tests/vectors/mip/3dm_config.yaml:558)
#[test]
fn case_coning_sculling_enable_ack() {
    check(
        "75650c0404f13e001d26",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":62,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `coning_sculling_enable_read_reply` (tests/vectors/mip/3dm_config.yaml:572)
#[test]
fn case_coning_sculling_enable_read_reply() {
    check(
        "75650c0704f13e00039e00c1da",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":62,\"ack_code\":0}},{\"descriptor\":158,\"name\":\"coning_sculling_enable_response\",\"values\":{\"enable\":false}}]}",
        ],
        false,
    );
}

/// `uart_baudrate_write_115200` (tests/vectors/mip/3dm_config.yaml:588)
#[test]
fn case_uart_baudrate_write_115200() {
    check(
        "75650c070740010001c200f8da",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":64,\"name\":\"uart_baudrate\",\"values\":{\"function\":1,\"baud\":115200}}]}",
        ],
        false,
    );
}

/// `uart_baudrate_ack` (tests/vectors/mip/3dm_config.yaml:598)
#[test]
fn case_uart_baudrate_ack() {
    check(
        "75650c0404f140001f2a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":64,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `uart_baudrate_read` (tests/vectors/mip/3dm_config.yaml:607)
#[test]
fn case_uart_baudrate_read() {
    check(
        "75650c030340022e64",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":64,\"name\":\"uart_baudrate\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `uart_baudrate_reply_921600` (tests/vectors/mip/3dm_config.yaml:619)
#[test]
fn case_uart_baudrate_reply_921600() {
    check(
        "75650c0a04f140000687000e1000d037",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":64,\"ack_code\":0}},{\"descriptor\":135,\"name\":\"uart_baudrate_response\",\"values\":{\"baud\":921600}}]}",
        ],
        false,
    );
}

/// `gpio_config_timestamp_falling_pullup` (tests/vectors/mip/3dm_config.yaml:636)
#[test]
fn case_gpio_config_timestamp_falling_pullup() {
    check(
        "75650c07074101010402044171",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":1,\"feature\":4,\"behavior\":{\"behavior\":2},\"pin_mode\":4}}]}",
        ],
        false,
    );
}

/// `gpio_config_output_low_pin1` (tests/vectors/mip/3dm_config.yaml:652)
#[test]
fn case_gpio_config_output_low_pin1() {
    check(
        "75650c07074101010102003a64",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":1,\"feature\":1,\"behavior\":{\"behavior\":2},\"pin_mode\":0}}]}",
        ],
        false,
    );
}

/// `gpio_config_input_pullup_pin3` (tests/vectors/mip/3dm_config.yaml:668)
#[test]
fn case_gpio_config_input_pullup_pin3() {
    check(
        "75650c07074101030101043f6e",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":3,\"feature\":1,\"behavior\":{\"behavior\":1},\"pin_mode\":4}}]}",
        ],
        false,
    );
}

/// `gpio_config_output_low_pin4` (tests/vectors/mip/3dm_config.yaml:684)
#[test]
fn case_gpio_config_output_low_pin4() {
    check(
        "75650c07074101040102003d70",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":4,\"feature\":1,\"behavior\":{\"behavior\":2},\"pin_mode\":0}}]}",
        ],
        false,
    );
}

/// `gpio_state_write_high_pin4` (tests/vectors/mip/3dm_config.yaml:700)
#[test]
fn case_gpio_state_write_high_pin4() {
    check(
        "75650c05054201040138e4",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":66,\"name\":\"gpio_state\",\"values\":{\"function\":1,\"pin\":4,\"state\":true}}]}",
        ],
        false,
    );
}

/// `gpio_state_write_low_pin4` (tests/vectors/mip/3dm_config.yaml:709)
#[test]
fn case_gpio_state_write_low_pin4() {
    check(
        "75650c05054201040037e3",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":66,\"name\":\"gpio_state\",\"values\":{\"function\":1,\"pin\":4,\"state\":false}}]}",
        ],
        false,
    );
}

/// `gpio_config_uart_port2_rx_pin2` (tests/vectors/mip/3dm_config.yaml:719)
#[test]
fn case_gpio_config_uart_port2_rx_pin2() {
    check(
        "75650c07074101020522005fb4",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":2,\"feature\":5,\"behavior\":{\"behavior\":34},\"pin_mode\":0}}]}",
        ],
        false,
    );
}

/// `gpio_config_pps_input_open_drain` (tests/vectors/mip/3dm_config.yaml:740)
#[test]
fn case_gpio_config_pps_input_open_drain() {
    check(
        "75650c07074101010201013b66",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":1,\"feature\":2,\"behavior\":{\"behavior\":1},\"pin_mode\":1}}]}",
        ],
        false,
    );
}

/// `gpio_config_encoder_b_pulldown` (tests/vectors/mip/3dm_config.yaml:761)
#[test]
fn case_gpio_config_encoder_b_pulldown() {
    check(
        "75650c07074101040302024178",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":4,\"feature\":3,\"behavior\":{\"behavior\":2},\"pin_mode\":2}}]}",
        ],
        false,
    );
}

/// `gpio_config_unused_pin3` (tests/vectors/mip/3dm_config.yaml:782)
#[test]
fn case_gpio_config_unused_pin3() {
    check(
        "75650c07074101030000003965",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":1,\"pin\":3,\"feature\":0,\"behavior\":{\"behavior\":0},\"pin_mode\":0}}]}",
        ],
        false,
    );
}

/// `gpio_config_save_all` (tests/vectors/mip/3dm_config.yaml:802)
#[test]
fn case_gpio_config_save_all() {
    check(
        "75650c040441030032a0",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":3,\"pin\":0}}]}",
        ],
        false,
    );
}

/// `gpio_config_read_pin1` (tests/vectors/mip/3dm_config.yaml:814)
#[test]
fn case_gpio_config_read_pin1() {
    check(
        "75650c0404410201329f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":65,\"name\":\"gpio_config\",\"values\":{\"function\":2,\"pin\":1}}]}",
        ],
        false,
    );
}

/// `gpio_config_reply_pps_output` (tests/vectors/mip/3dm_config.yaml:826)
#[test]
fn case_gpio_config_reply_pps_output() {
    check(
        "75650c0a04f1410006c101020200f225",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":65,\"ack_code\":0}},{\"descriptor\":193,\"name\":\"gpio_config_response\",\"values\":{\"pin\":1,\"feature\":2,\"behavior\":{\"behavior\":2},\"pin_mode\":0}}]}",
        ],
        false,
    );
}

/// `gpio_config_reply_timestamp_either` (tests/vectors/mip/3dm_config.yaml:847)
#[test]
fn case_gpio_config_reply_timestamp_either() {
    check(
        "75650c0a04f1410006c102040304fa35",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":65,\"ack_code\":0}},{\"descriptor\":193,\"name\":\"gpio_config_response\",\"values\":{\"pin\":2,\"feature\":4,\"behavior\":{\"behavior\":3},\"pin_mode\":4}}]}",
        ],
        false,
    );
}

/// `gpio_state_read_pin3` (tests/vectors/mip/3dm_config.yaml:868)
#[test]
fn case_gpio_state_read_pin3() {
    check(
        "75650c040442020335a4",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":66,\"name\":\"gpio_state\",\"values\":{\"function\":2,\"pin\":3}}]}",
        ],
        false,
    );
}

/// `gpio_state_reply_pin3_high` (tests/vectors/mip/3dm_config.yaml:880)
#[test]
fn case_gpio_state_reply_pin3_high() {
    check(
        "75650c0804f1420004c20301ef33",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":66,\"ack_code\":0}},{\"descriptor\":194,\"name\":\"gpio_state_response\",\"values\":{\"pin\":3,\"state\":true}}]}",
        ],
        false,
    );
}

/// `odometer_config_write_quadrature` (tests/vectors/mip/3dm_config.yaml:896)
#[test]
fn case_odometer_config_write_quadrature() {
    check(
        "75650c0c0c430102447a00003c23d70a4293",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":67,\"name\":\"odometer_config\",\"values\":{\"function\":1,\"mode\":2,\"scaling\":1000.0,\"uncertainty\":0.009999999776482582}}]}",
        ],
        false,
    );
}

/// `odometer_config_reply_disabled` (tests/vectors/mip/3dm_config.yaml:916)
#[test]
fn case_odometer_config_reply_disabled() {
    check(
        "75650c0f04f143000bc300c37a00003d800000f54f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":67,\"ack_code\":0}},{\"descriptor\":195,\"name\":\"odometer_config_response\",\"values\":{\"mode\":0,\"scaling\":-250.0,\"uncertainty\":0.0625}}]}",
        ],
        false,
    );
}

/// `advanced_lowpass_filter_write_accel` (tests/vectors/mip/3dm_config.yaml:938)
#[test]
fn case_advanced_lowpass_filter_write_accel() {
    check(
        "75650c090950010401000000004e80",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":80,\"name\":\"advanced_lowpass_filter\",\"values\":{\"function\":1,\"target_descriptor\":4,\"enable\":true,\"manual\":false,\"frequency\":0,\"reserved\":0}}]}",
        ],
        false,
    );
}

/// `advanced_lowpass_filter_ack` (tests/vectors/mip/3dm_config.yaml:959)
#[test]
fn case_advanced_lowpass_filter_ack() {
    check(
        "75650c0404f150002f4a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":80,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `advanced_lowpass_filter_read_gyro` (tests/vectors/mip/3dm_config.yaml:968)
#[test]
fn case_advanced_lowpass_filter_read_gyro() {
    check(
        "75650c040450020545d0",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":80,\"name\":\"advanced_lowpass_filter\",\"values\":{\"function\":2,\"target_descriptor\":5}}]}",
        ],
        false,
    );
}

/// `advanced_lowpass_filter_reply_gyro` (tests/vectors/mip/3dm_config.yaml:980)
#[test]
fn case_advanced_lowpass_filter_reply_gyro() {
    check(
        "75650c0c04f15000088b0501010064003526",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":80,\"ack_code\":0}},{\"descriptor\":139,\"name\":\"advanced_lowpass_filter_response\",\"values\":{\"target_descriptor\":5,\"enable\":true,\"manual\":true,\"frequency\":100,\"reserved\":0}}]}",
        ],
        false,
    );
}

/// `advanced_lowpass_filter_default_all_cv7` (tests/vectors/mip/3dm_config.yaml:1003)
#[test]
fn case_advanced_lowpass_filter_default_all_cv7() {
    check(
        "75650c040450050043d1",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":80,\"name\":\"advanced_lowpass_filter\",\"values\":{\"function\":5,\"target_descriptor\":0}}]}",
        ],
        false,
    );
}

/// `complementary_filter_write` (tests/vectors/mip/3dm_config.yaml:1015)
#[test]
fn case_complementary_filter_write() {
    check(
        "75650c0d0d5101010140a0000040a000001452",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":81,\"name\":\"complementary_filter\",\"values\":{\"function\":1,\"pitch_roll_enable\":true,\"heading_enable\":true,\"pitch_roll_time_constant\":5.0,\"heading_time_constant\":5.0}}]}",
        ],
        false,
    );
}

/// `complementary_filter_ack` (tests/vectors/mip/3dm_config.yaml:1038)
#[test]
fn case_complementary_filter_ack() {
    check(
        "75650c0404f15100304c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":81,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `complementary_filter_reply` (tests/vectors/mip/3dm_config.yaml:1051)
#[test]
fn case_complementary_filter_reply() {
    check(
        "75650c1004f151000c97010041200000447a0000ffd5",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":81,\"ack_code\":0}},{\"descriptor\":151,\"name\":\"complementary_filter_response\",\"values\":{\"pitch_roll_enable\":true,\"heading_enable\":false,\"pitch_roll_time_constant\":10.0,\"heading_time_constant\":1000.0}}]}",
        ],
        false,
    );
}

/// `sensor_range_write_accel_8g` (tests/vectors/mip/3dm_config.yaml:1076)
#[test]
fn case_sensor_range_write_accel_8g() {
    check(
        "75650c0505520101034720",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":82,\"name\":\"sensor_range\",\"values\":{\"function\":1,\"sensor\":1,\"setting\":3}}]}",
        ],
        false,
    );
}

/// `sensor_range_save_all` (tests/vectors/mip/3dm_config.yaml:1089)
#[test]
fn case_sensor_range_save_all() {
    check(
        "75650c040452030043d3",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":82,\"name\":\"sensor_range\",\"values\":{\"function\":3,\"sensor\":0}}]}",
        ],
        false,
    );
}

/// `sensor_range_reply_gyro` (tests/vectors/mip/3dm_config.yaml:1101)
#[test]
fn case_sensor_range_reply_gyro() {
    check(
        "75650c0804f1520004d202020fc2",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":82,\"ack_code\":0}},{\"descriptor\":210,\"name\":\"sensor_range_response\",\"values\":{\"sensor\":2,\"setting\":2}}]}",
        ],
        false,
    );
}

/// `get_calibrated_sensor_ranges_accel` (tests/vectors/mip/3dm_config.yaml:1116)
#[test]
fn case_get_calibrated_sensor_ranges_accel() {
    check(
        "75650c030353014089",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":83,\"name\":\"get_calibrated_sensor_ranges\",\"values\":{\"sensor\":1}}]}",
        ],
        false,
    );
}

/// `calibrated_sensor_ranges_accel` (tests/vectors/mip/3dm_config.yaml:1128)
#[test]
fn case_calibrated_sensor_ranges_accel() {
    check(
        "75650c1704f1530013d30103024080000003410000000441800000fa6b",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":83,\"ack_code\":0}},{\"descriptor\":211,\"name\":\"calibrated_sensor_ranges\",\"values\":{\"sensor\":1,\"num_ranges\":3,\"ranges\":[{\"setting\":2,\"range\":4.0},{\"setting\":3,\"range\":8.0},{\"setting\":4,\"range\":16.0}]}}]}",
        ],
        false,
    );
}

/// `lowpass_filter_write_accel_manual` (tests/vectors/mip/3dm_config.yaml:1150)
#[test]
fn case_lowpass_filter_write_accel_manual() {
    check(
        "75650c0b0b540180040101424800006152",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":84,\"name\":\"lowpass_filter\",\"values\":{\"function\":1,\"desc_set\":128,\"field_desc\":4,\"enable\":true,\"manual\":true,\"frequency\":50.0}}]}",
        ],
        false,
    );
}

/// `lowpass_filter_read_comp_rate` (tests/vectors/mip/3dm_config.yaml:1173)
#[test]
fn case_lowpass_filter_read_comp_rate() {
    check(
        "75650c05055402820ed638",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":84,\"name\":\"lowpass_filter\",\"values\":{\"function\":2,\"desc_set\":130,\"field_desc\":14}}]}",
        ],
        false,
    );
}

/// `lowpass_filter_reply_auto` (tests/vectors/mip/3dm_config.yaml:1187)
#[test]
fn case_lowpass_filter_reply_auto() {
    check(
        "75650c0e04f154000ad4820e010041c80000b592",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":84,\"ack_code\":0}},{\"descriptor\":212,\"name\":\"lowpass_filter_response\",\"values\":{\"desc_set\":130,\"field_desc\":14,\"enable\":true,\"manual\":false,\"frequency\":25.0}}]}",
        ],
        false,
    );
}

/// `lowpass_filter_default_all` (tests/vectors/mip/3dm_config.yaml:1209)
#[test]
fn case_lowpass_filter_default_all() {
    check(
        "75650c050554050000492f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":84,\"name\":\"lowpass_filter\",\"values\":{\"function\":5,\"desc_set\":0,\"field_desc\":0}}]}",
        ],
        false,
    );
}

/// `capture_gyro_bias_reply_table_published` (tests/vectors/mip/3dm_config.yaml:1225)
#[test]
fn case_capture_gyro_bias_reply_table_published() {
    check(
        "75650c0404f139000e9b000000000000000000000000cf19",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c0404f139000e9b000000000000000000000000cf19\"}"],
        true,
    );
}

/// `mag_soft_iron_copy_paste_published` (tests/vectors/mip/3dm_config.yaml:1239)
#[test]
fn case_mag_soft_iron_copy_paste_published() {
    check(
        "75650c27273b013f8000000000000000000000000000003f80000000000000000000003f800000ad59",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"75650c27273b013f8000000000000000000000000000003f80000000000000000000003f800000ad59\"}",
        ],
        true,
    );
}

/// `mag_soft_iron_ack_table_published` (tests/vectors/mip/3dm_config.yaml:1253)
#[test]
fn case_mag_soft_iron_ack_table_published() {
    check(
        "75650c1204f13b001a20",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c1204f13b001a20\"}"],
        true,
    );
}

/// `coning_sculling_enable_ack_table_published` (tests/vectors/mip/3dm_config.yaml:1266)
#[test]
fn case_coning_sculling_enable_ack_table_published() {
    check(
        "75650c0404f138001d26",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c0404f138001d26\"}"],
        true,
    );
}

/// `advanced_lowpass_filter_table_published` (tests/vectors/mip/3dm_config.yaml:1279)
#[test]
fn case_advanced_lowpass_filter_table_published() {
    check(
        "75650c090950010401000000004c6d",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c090950010401000000004c6d\"}"],
        true,
    );
}

/// `complementary_filter_copy_paste_published` (tests/vectors/mip/3dm_config.yaml:1292)
#[test]
fn case_complementary_filter_copy_paste_published() {
    check(
        "75650c09095101040100000000",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c09095101040100000000\"}"],
        true,
    );
}

/// `setup_imu_message_format_write` (tests/vectors/mip/3dm_streaming.yaml:12)
#[test]
fn case_setup_imu_message_format_write() {
    check(
        "75650c0d0d08010312000a04000a05000a45f2",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":1,\"num_descriptors\":3,\"descriptors\":[{\"descriptor\":18,\"decimation\":10},{\"descriptor\":4,\"decimation\":10},{\"descriptor\":5,\"decimation\":10}]}}]}",
        ],
        false,
    );
}

/// `setup_imu_message_format_ack` (tests/vectors/mip/3dm_streaming.yaml:30)
#[test]
fn case_setup_imu_message_format_ack() {
    check(
        "75650c0404f10800e7ba",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":8,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `imu_message_format_write_ack_table_published` (tests/vectors/mip/3dm_streaming.yaml:39)
#[test]
fn case_imu_message_format_write_ack_table_published() {
    check(
        "75650c0404f10100e7ba",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c0404f10100e7ba\"}"],
        true,
    );
}

/// `setup_filter_message_format_write` (tests/vectors/mip/3dm_streaming.yaml:52)
#[test]
fn case_setup_filter_message_format_write() {
    check(
        "75650c13130a010511000a10000a01000a02000a03000a7562",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":10,\"name\":\"filter_message_format\",\"values\":{\"function\":1,\"num_descriptors\":5,\"descriptors\":[{\"descriptor\":17,\"decimation\":10},{\"descriptor\":16,\"decimation\":10},{\"descriptor\":1,\"decimation\":10},{\"descriptor\":2,\"decimation\":10},{\"descriptor\":3,\"decimation\":10}]}}]}",
        ],
        false,
    );
}

/// `filter_message_format_ack` (tests/vectors/mip/3dm_streaming.yaml:72)
#[test]
fn case_filter_message_format_ack() {
    check(
        "75650c0404f10a00e9be",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":10,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `save_message_formats_command` (tests/vectors/mip/3dm_streaming.yaml:82)
#[test]
fn case_save_message_formats_command() {
    check(
        "75650c0804080300040a03000e31",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":3,\"num_descriptors\":0}},{\"descriptor\":10,\"name\":\"filter_message_format\",\"values\":{\"function\":3,\"num_descriptors\":0}}]}",
        ],
        false,
    );
}

/// `message_formats_two_acks` (tests/vectors/mip/3dm_streaming.yaml:93)
#[test]
fn case_message_formats_two_acks() {
    check(
        "75650c0804f1080004f10a00ea71",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":8,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":10,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `save_message_formats_reply_table_published` (tests/vectors/mip/3dm_streaming.yaml:106)
#[test]
fn case_save_message_formats_reply_table_published() {
    check(
        "75650c0804f1080004f10a00e9be",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c0804f1080004f10a00e9be\"}"],
        true,
    );
}

/// `setup_enable_streams_command` (tests/vectors/mip/3dm_streaming.yaml:119)
#[test]
fn case_setup_enable_streams_command() {
    check(
        "75650c0a0511010101051101030124cc",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"device_selector\":1,\"enable\":1}},{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"device_selector\":3,\"enable\":1}}]}",
        ],
        false,
    );
}

/// `setup_enable_streams_reply` (tests/vectors/mip/3dm_streaming.yaml:131)
#[test]
fn case_setup_enable_streams_reply() {
    check(
        "75650c0804f1110004f11100fab5",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `setup_poll_cf_euler` (tests/vectors/mip/3dm_streaming.yaml:141)
#[test]
fn case_setup_poll_cf_euler() {
    check(
        "75650c07070100010c000002fc",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":1,\"name\":\"poll_imu_data\",\"values\":{\"option\":0,\"num_descriptors\":1,\"descriptors\":[{\"descriptor\":12,\"reserved\":0}]}}]}",
        ],
        false,
    );
}

/// `setup_poll_cf_euler_table_published` (tests/vectors/mip/3dm_streaming.yaml:153)
#[test]
fn case_setup_poll_cf_euler_table_published() {
    check(
        "75650c070701000006000002fc",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c070701000006000002fc\"}"],
        true,
    );
}

/// `poll_imu_ack` (tests/vectors/mip/3dm_streaming.yaml:168)
#[test]
fn case_poll_imu_ack() {
    check(
        "75650c0404f10100e0ac",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `poll_imu_stored_format` (tests/vectors/mip/3dm_streaming.yaml:180)
#[test]
fn case_poll_imu_stored_format() {
    check(
        "75650c0404010000efda",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":1,\"name\":\"poll_imu_data\",\"values\":{\"option\":0,\"num_descriptors\":0,\"descriptors\":[]}}]}",
        ],
        false,
    );
}

/// `poll_imu_specified_format` (tests/vectors/mip/3dm_streaming.yaml:192)
#[test]
fn case_poll_imu_specified_format() {
    check(
        "75650c0a0a0100020400000500000627",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":1,\"name\":\"poll_imu_data\",\"values\":{\"option\":0,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":4,\"reserved\":0},{\"descriptor\":5,\"reserved\":0}]}}]}",
        ],
        false,
    );
}

/// `poll_imu_suppress_ack` (tests/vectors/mip/3dm_streaming.yaml:204)
#[test]
fn case_poll_imu_suppress_ack() {
    check(
        "75650c0707010101040000fbe9",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":1,\"name\":\"poll_imu_data\",\"values\":{\"option\":1,\"num_descriptors\":1,\"descriptors\":[{\"descriptor\":4,\"reserved\":0}]}}]}",
        ],
        false,
    );
}

/// `poll_gnss_stored_format` (tests/vectors/mip/3dm_streaming.yaml:218)
#[test]
fn case_poll_gnss_stored_format() {
    check(
        "75650c0404020000f0dd",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":2,\"name\":\"poll_gnss_data\",\"values\":{\"option\":0,\"num_descriptors\":0,\"descriptors\":[]}}]}",
        ],
        false,
    );
}

/// `poll_gnss_specified_format` (tests/vectors/mip/3dm_streaming.yaml:228)
#[test]
fn case_poll_gnss_specified_format() {
    check(
        "75650c0a0a020002030000050000062a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":2,\"name\":\"poll_gnss_data\",\"values\":{\"option\":0,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":3,\"reserved\":0},{\"descriptor\":5,\"reserved\":0}]}}]}",
        ],
        false,
    );
}

/// `poll_gnss_ack` (tests/vectors/mip/3dm_streaming.yaml:240)
#[test]
fn case_poll_gnss_ack() {
    check(
        "75650c0404f10200e1ae",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":2,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `poll_filter_stored_format` (tests/vectors/mip/3dm_streaming.yaml:249)
#[test]
fn case_poll_filter_stored_format() {
    check(
        "75650c0404030000f1e0",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":3,\"name\":\"poll_filter_data\",\"values\":{\"option\":0,\"num_descriptors\":0,\"descriptors\":[]}}]}",
        ],
        false,
    );
}

/// `poll_filter_specified_format` (tests/vectors/mip/3dm_streaming.yaml:259)
#[test]
fn case_poll_filter_specified_format() {
    check(
        "75650c0a0a030002010000020000021e",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":3,\"name\":\"poll_filter_data\",\"values\":{\"option\":0,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":1,\"reserved\":0},{\"descriptor\":2,\"reserved\":0}]}}]}",
        ],
        false,
    );
}

/// `poll_filter_ack` (tests/vectors/mip/3dm_streaming.yaml:271)
#[test]
fn case_poll_filter_ack() {
    check(
        "75650c0404f10300e2b0",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":3,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `get_imu_base_rate_command` (tests/vectors/mip/3dm_streaming.yaml:281)
#[test]
fn case_get_imu_base_rate_command() {
    check(
        "75650c020206f0f7",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":6,\"name\":\"get_imu_base_rate\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_imu_base_rate_reply` (tests/vectors/mip/3dm_streaming.yaml:291)
#[test]
fn case_get_imu_base_rate_reply() {
    check(
        "75650c0804f1060004830064d46b",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":6,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"imu_base_rate\",\"values\":{\"rate\":100}}]}",
        ],
        false,
    );
}

/// `get_gnss_base_rate_command` (tests/vectors/mip/3dm_streaming.yaml:302)
#[test]
fn case_get_gnss_base_rate_command() {
    check(
        "75650c020207f1f8",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":7,\"name\":\"get_gnss_base_rate\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_gnss_base_rate_reply` (tests/vectors/mip/3dm_streaming.yaml:312)
#[test]
fn case_get_gnss_base_rate_reply() {
    check(
        "75650c0804f10700048400047614",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":7,\"ack_code\":0}},{\"descriptor\":132,\"name\":\"gnss_base_rate\",\"values\":{\"rate\":4}}]}",
        ],
        false,
    );
}

/// `get_filter_base_rate_command` (tests/vectors/mip/3dm_streaming.yaml:322)
#[test]
fn case_get_filter_base_rate_command() {
    check(
        "75650c02020bf5fc",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":11,\"name\":\"get_filter_base_rate\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_filter_base_rate_reply` (tests/vectors/mip/3dm_streaming.yaml:332)
#[test]
fn case_get_filter_base_rate_reply() {
    check(
        "75650c0804f10b00048a0064e09e",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":11,\"ack_code\":0}},{\"descriptor\":138,\"name\":\"filter_base_rate\",\"values\":{\"rate\":100}}]}",
        ],
        false,
    );
}

/// `imu_message_format_write` (tests/vectors/mip/3dm_streaming.yaml:343)
#[test]
fn case_imu_message_format_write() {
    check(
        "75650c0a0a08010204000a05000a22a0",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":1,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":4,\"decimation\":10},{\"descriptor\":5,\"decimation\":10}]}}]}",
        ],
        false,
    );
}

/// `imu_message_format_read` (tests/vectors/mip/3dm_streaming.yaml:355)
#[test]
fn case_imu_message_format_read() {
    check(
        "75650c0404080200f8f3",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":2,\"num_descriptors\":0}}]}",
        ],
        false,
    );
}

/// `imu_message_format_read_reply` (tests/vectors/mip/3dm_streaming.yaml:365)
#[test]
fn case_imu_message_format_read_reply() {
    check(
        "75650c0d04f1080009800204000a05000a980f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":8,\"ack_code\":0}},{\"descriptor\":128,\"name\":\"imu_message_format_response\",\"values\":{\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":4,\"decimation\":10},{\"descriptor\":5,\"decimation\":10}]}}]}",
        ],
        false,
    );
}

/// `imu_message_format_read_reply_table_published` (tests/vectors/mip/3dm_streaming.yaml:384)
#[test]
fn case_imu_message_format_read_reply_table_published() {
    check(
        "75650c0d04f1080009800203000a04000a980f",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c0d04f1080009800203000a04000a980f\"}"],
        true,
    );
}

/// `imu_message_format_load` (tests/vectors/mip/3dm_streaming.yaml:398)
#[test]
fn case_imu_message_format_load() {
    check(
        "75650c0404080400faf7",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":4,\"num_descriptors\":0}}]}",
        ],
        false,
    );
}

/// `gnss_message_format_write` (tests/vectors/mip/3dm_streaming.yaml:408)
#[test]
fn case_gnss_message_format_write() {
    check(
        "75650c0a0a0901020300040500041685",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":9,\"name\":\"gnss_message_format\",\"values\":{\"function\":1,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":3,\"decimation\":4},{\"descriptor\":5,\"decimation\":4}]}}]}",
        ],
        false,
    );
}

/// `gnss_message_format_ack` (tests/vectors/mip/3dm_streaming.yaml:420)
#[test]
fn case_gnss_message_format_ack() {
    check(
        "75650c0404f10900e8bc",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":9,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gnss_message_format_read` (tests/vectors/mip/3dm_streaming.yaml:429)
#[test]
fn case_gnss_message_format_read() {
    check(
        "75650c0404090200f9f6",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":9,\"name\":\"gnss_message_format\",\"values\":{\"function\":2,\"num_descriptors\":0}}]}",
        ],
        false,
    );
}

/// `gnss_message_format_read_table_published` (tests/vectors/mip/3dm_streaming.yaml:438)
#[test]
fn case_gnss_message_format_read_table_published() {
    check(
        "75650c0404090200f9f3",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c0404090200f9f3\"}"],
        true,
    );
}

/// `gnss_message_format_read_reply` (tests/vectors/mip/3dm_streaming.yaml:450)
#[test]
fn case_gnss_message_format_read_reply() {
    check(
        "75650c0d04f109000981020300040500048dfe",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":9,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"gnss_message_format_response\",\"values\":{\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":3,\"decimation\":4},{\"descriptor\":5,\"decimation\":4}]}}]}",
        ],
        false,
    );
}

/// `filter_message_format_write` (tests/vectors/mip/3dm_streaming.yaml:462)
#[test]
fn case_filter_message_format_write() {
    check(
        "75650c0a0a0a01020100010200010c6a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":10,\"name\":\"filter_message_format\",\"values\":{\"function\":1,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":1,\"decimation\":1},{\"descriptor\":2,\"decimation\":1}]}}]}",
        ],
        false,
    );
}

/// `filter_message_format_write_copy_paste_published` (tests/vectors/mip/3dm_streaming.yaml:473)
#[test]
fn case_filter_message_format_write_copy_paste_published() {
    check(
        "75650c0a0a0901020300040500041685",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":9,\"name\":\"gnss_message_format\",\"values\":{\"function\":1,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":3,\"decimation\":4},{\"descriptor\":5,\"decimation\":4}]}}]}",
        ],
        false,
    );
}

/// `filter_message_format_read` (tests/vectors/mip/3dm_streaming.yaml:492)
#[test]
fn case_filter_message_format_read() {
    check(
        "75650c04040a0200faf9",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":10,\"name\":\"filter_message_format\",\"values\":{\"function\":2,\"num_descriptors\":0}}]}",
        ],
        false,
    );
}

/// `filter_message_format_read_copy_paste_published` (tests/vectors/mip/3dm_streaming.yaml:501)
#[test]
fn case_filter_message_format_read_copy_paste_published() {
    check(
        "75650c0404090200f9f6",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":9,\"name\":\"gnss_message_format\",\"values\":{\"function\":2,\"num_descriptors\":0}}]}",
        ],
        false,
    );
}

/// `filter_message_format_read_reply` (tests/vectors/mip/3dm_streaming.yaml:517)
#[test]
fn case_filter_message_format_read_reply() {
    check(
        "75650c0d04f10a0009820201000102000184ed",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":10,\"ack_code\":0}},{\"descriptor\":130,\"name\":\"filter_message_format_response\",\"values\":{\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":1,\"decimation\":1},{\"descriptor\":2,\"decimation\":1}]}}]}",
        ],
        false,
    );
}

/// `two_message_formats_in_one_packet` (tests/vectors/mip/3dm_streaming.yaml:530)
#[test]
fn case_two_message_formats_in_one_packet() {
    check(
        "75650c200d08010312000a04000a05000a130a010511000a10000a01000a02000a03000ad43d",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":1,\"num_descriptors\":3,\"descriptors\":[{\"descriptor\":18,\"decimation\":10},{\"descriptor\":4,\"decimation\":10},{\"descriptor\":5,\"decimation\":10}]}},{\"descriptor\":10,\"name\":\"filter_message_format\",\"values\":{\"function\":1,\"num_descriptors\":5,\"descriptors\":[{\"descriptor\":17,\"decimation\":10},{\"descriptor\":16,\"decimation\":10},{\"descriptor\":1,\"decimation\":10},{\"descriptor\":2,\"decimation\":10},{\"descriptor\":3,\"decimation\":10}]}}]}",
        ],
        false,
    );
}

/// `data_stream_imu_on` (tests/vectors/mip/3dm_streaming.yaml:558)
#[test]
fn case_data_stream_imu_on() {
    check(
        "75650c050511010101041a",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"device_selector\":1,\"enable\":1}}]}",
        ],
        false,
    );
}

/// `data_stream_imu_off` (tests/vectors/mip/3dm_streaming.yaml:569)
#[test]
fn case_data_stream_imu_off() {
    check(
        "75650c0505110101000319",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"device_selector\":1,\"enable\":0}}]}",
        ],
        false,
    );
}

/// `data_stream_ack` (tests/vectors/mip/3dm_streaming.yaml:579)
#[test]
fn case_data_stream_ack() {
    check(
        "75650c0404f11100f0cc",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `data_stream_gx5_read_filter` (tests/vectors/mip/3dm_streaming.yaml:588)
#[test]
fn case_data_stream_gx5_read_filter() {
    check(
        "75650c0505110203000620",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"gx5_45\",\"values\":{\"function\":2,\"device_selector\":3,\"enable\":0}}]}",
        ],
        false,
    );
}

/// `data_stream_gx5_read_reply` (tests/vectors/mip/3dm_streaming.yaml:602)
#[test]
fn case_data_stream_gx5_read_reply() {
    check(
        "75650c0804f11100048503018156",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}},{\"descriptor\":133,\"name\":\"data_stream_control_response\",\"device\":\"gx5_45\",\"values\":{\"device_selector\":3,\"enabled\":1}}]}",
        ],
        false,
    );
}

/// `gnss_constellation_settings_write` (tests/vectors/mip/3dm_streaming.yaml:617)
#[test]
fn case_gnss_constellation_settings_write() {
    check(
        "75650c121221010020020001081000000601080e0000845a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":33,\"name\":\"gnss_constellation_settings\",\"values\":{\"function\":1,\"max_channels\":32,\"config_count\":2,\"settings\":[{\"constellation_id\":0,\"enable\":1,\"reserved_channels\":8,\"max_channels\":16,\"option_flags\":0},{\"constellation_id\":6,\"enable\":1,\"reserved_channels\":8,\"max_channels\":14,\"option_flags\":0}]}}]}",
        ],
        false,
    );
}

/// `gnss_constellation_settings_ack` (tests/vectors/mip/3dm_streaming.yaml:635)
#[test]
fn case_gnss_constellation_settings_ack() {
    check(
        "75650c0404f1210000ec",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":33,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gnss_constellation_settings_read` (tests/vectors/mip/3dm_streaming.yaml:644)
#[test]
fn case_gnss_constellation_settings_read() {
    check(
        "75650c06062102000000157a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":33,\"name\":\"gnss_constellation_settings\",\"values\":{\"function\":2,\"max_channels\":0,\"config_count\":0}}]}",
        ],
        false,
    );
}

/// `gnss_constellation_settings_read_reply` (tests/vectors/mip/3dm_streaming.yaml:656)
#[test]
fn case_gnss_constellation_settings_read_reply() {
    check(
        "75650c2304f121001fa000200020040001081000000601080e0000010101030000050100030001683c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":33,\"ack_code\":0}},{\"descriptor\":160,\"name\":\"gnss_constellation_settings_response\",\"values\":{\"max_channels_available\":32,\"max_channels\":32,\"config_count\":4,\"settings\":[{\"constellation_id\":0,\"enable\":1,\"reserved_channels\":8,\"max_channels\":16,\"option_flags\":0},{\"constellation_id\":6,\"enable\":1,\"reserved_channels\":8,\"max_channels\":14,\"option_flags\":0},{\"constellation_id\":1,\"enable\":1,\"reserved_channels\":1,\"max_channels\":3,\"option_flags\":0},{\"constellation_id\":5,\"enable\":1,\"reserved_channels\":0,\"max_channels\":3,\"option_flags\":1}]}}]}",
        ],
        false,
    );
}

/// `gnss_sbas_settings_write` (tests/vectors/mip/3dm_streaming.yaml:684)
#[test]
fn case_gnss_sbas_settings_write() {
    check(
        "75650c0b0b22010100030200780079165c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":34,\"name\":\"gnss_sbas_settings\",\"values\":{\"function\":1,\"enable_sbas\":1,\"sbas_options\":3,\"num_included_prns\":2,\"included_prns\":[120,121]}}]}",
        ],
        false,
    );
}

/// `gnss_sbas_settings_ack` (tests/vectors/mip/3dm_streaming.yaml:701)
#[test]
fn case_gnss_sbas_settings_ack() {
    check(
        "75650c0404f1220001ee",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":34,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gnss_sbas_settings_read_reply_three_prns` (tests/vectors/mip/3dm_streaming.yaml:710)
#[test]
fn case_gnss_sbas_settings_read_reply_three_prns() {
    check(
        "75650c1004f122000ca10100070300780079007a30d5",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":34,\"ack_code\":0}},{\"descriptor\":161,\"name\":\"gnss_sbas_settings_response\",\"values\":{\"enable_sbas\":1,\"sbas_options\":7,\"num_included_prns\":3,\"included_prns\":[120,121,122]}}]}",
        ],
        false,
    );
}

/// `gnss_sbas_settings_read_short` (tests/vectors/mip/3dm_streaming.yaml:731)
#[test]
fn case_gnss_sbas_settings_read_short() {
    check(
        "75650c030322021028",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":34,\"name\":\"gnss_sbas_settings\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `gnss_sbas_settings_write_include_all` (tests/vectors/mip/3dm_streaming.yaml:741)
#[test]
fn case_gnss_sbas_settings_write_include_all() {
    check(
        "75650c07072201010003001ba9",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":34,\"name\":\"gnss_sbas_settings\",\"values\":{\"function\":1,\"enable_sbas\":1,\"sbas_options\":3,\"num_included_prns\":0}}]}",
        ],
        false,
    );
}

/// `gnss_sbas_settings_read_reply_disabled` (tests/vectors/mip/3dm_streaming.yaml:756)
#[test]
fn case_gnss_sbas_settings_read_reply_disabled() {
    check(
        "75650c0a04f1220006a100000000ae7f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":34,\"ack_code\":0}},{\"descriptor\":161,\"name\":\"gnss_sbas_settings_response\",\"values\":{\"enable_sbas\":0,\"sbas_options\":0,\"num_included_prns\":0,\"included_prns\":[]}}]}",
        ],
        false,
    );
}

/// `gnss_assisted_fix_enable` (tests/vectors/mip/3dm_streaming.yaml:770)
#[test]
fn case_gnss_assisted_fix_enable() {
    check(
        "75650c0505230101ff1460",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":35,\"name\":\"gnss_assisted_fix_control\",\"values\":{\"function\":1,\"option\":1,\"flags\":255}}]}",
        ],
        false,
    );
}

/// `gnss_assisted_fix_ack` (tests/vectors/mip/3dm_streaming.yaml:780)
#[test]
fn case_gnss_assisted_fix_ack() {
    check(
        "75650c0404f1230002f0",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":35,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gnss_assisted_fix_read` (tests/vectors/mip/3dm_streaming.yaml:789)
#[test]
fn case_gnss_assisted_fix_read() {
    check(
        "75650c0505230200ff1461",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":35,\"name\":\"gnss_assisted_fix_control\",\"values\":{\"function\":2,\"option\":0,\"flags\":255}}]}",
        ],
        false,
    );
}

/// `gnss_assisted_fix_read_reply` (tests/vectors/mip/3dm_streaming.yaml:801)
#[test]
fn case_gnss_assisted_fix_read_reply() {
    check(
        "75650c0804f1230004a201ffac13",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":35,\"ack_code\":0}},{\"descriptor\":162,\"name\":\"gnss_assisted_fix_control_response\",\"values\":{\"option\":1,\"flags\":255}}]}",
        ],
        false,
    );
}

/// `gnss_assist_time_update_command` (tests/vectors/mip/3dm_streaming.yaml:813)
#[test]
fn case_gnss_assist_time_update_command() {
    check(
        "75650c1111240140e722c6b851eb85078140a000001deb",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":1,\"tow\":47382.21,\"week_number\":1921,\"accuracy\":5.0}}]}",
        ],
        false,
    );
}

/// `gnss_assist_time_update_ack` (tests/vectors/mip/3dm_streaming.yaml:827)
#[test]
fn case_gnss_assist_time_update_ack() {
    check(
        "75650c0404f1240003f2",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":36,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gnss_assist_time_update_read` (tests/vectors/mip/3dm_streaming.yaml:836)
#[test]
fn case_gnss_assist_time_update_read() {
    check(
        "75650c1111240200000000000000000000000000002e12",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":2,\"tow\":0.0,\"week_number\":0,\"accuracy\":0.0}}]}",
        ],
        false,
    );
}

/// `gnss_assist_time_update_read_reply` (tests/vectors/mip/3dm_streaming.yaml:848)
#[test]
fn case_gnss_assist_time_update_read_reply() {
    check(
        "75650c1404f1240010a340e722c6b851eb85078140a00000b6e7",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":36,\"ack_code\":0}},{\"descriptor\":163,\"name\":\"gnss_assist_time_update_response\",\"values\":{\"tow\":47382.21,\"week_number\":1921,\"accuracy\":5.0}}]}",
        ],
        false,
    );
}

/// `device_status_basic_command` (tests/vectors/mip/3dm_streaming.yaml:862)
#[test]
fn case_device_status_basic_command() {
    check(
        "75650c050564186b01d87f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":100,\"name\":\"device_status\",\"values\":{\"model_number\":6251,\"status_selector\":1}}]}",
        ],
        false,
    );
}

/// `device_status_basic_reply` (tests/vectors/mip/3dm_streaming.yaml:872)
#[test]
fn case_device_status_basic_reply() {
    check(
        "75650c1304f164000f90186b010000000000010000ea60c0cc",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":100,\"ack_code\":0}},{\"descriptor\":144,\"name\":\"device_status_response\",\"values\":{\"model_number\":6251,\"status_selector\":1,\"status\":{\"status_flags\":0,\"system_state\":1,\"system_timer\":60000}}}]}",
        ],
        false,
    );
}

/// `device_status_diagnostic_command` (tests/vectors/mip/3dm_streaming.yaml:894)
#[test]
fn case_device_status_diagnostic_command() {
    check(
        "75650c050564186b02d980",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":100,\"name\":\"device_status\",\"values\":{\"model_number\":6251,\"status_selector\":2}}]}",
        ],
        false,
    );
}

/// `device_status_diagnostic_reply` (tests/vectors/mip/3dm_streaming.yaml:904)
#[test]
fn case_device_status_diagnostic_reply() {
    check(
        "75650c4f04f164004b90186b020000000000010000ea60010000003c0000e86c0101010000000000000000000000000001e240000003150000000000000000000075300000ea5e00000002000000f00000e9663669",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":100,\"ack_code\":0}},{\"descriptor\":144,\"name\":\"device_status_response\",\"values\":{\"model_number\":6251,\"status_selector\":2,\"status\":{\"status_flags\":0,\"system_state\":1,\"system_timer\":60000,\"gnss_power_state\":1,\"pps_pulse_count\":60,\"last_pps_time\":59500,\"imu_stream_enabled\":1,\"gnss_stream_enabled\":1,\"filter_stream_enabled\":1,\"imu_dropped_packets\":0,\"gnss_dropped_packets\":0,\"filter_dropped_packets\":0,\"com_bytes_written\":123456,\"com_bytes_read\":789,\"com_write_overruns\":0,\"imu_parse_errors\":0,\"imu_messages_read\":30000,\"last_imu_message_time\":59998,\"gnss_parse_errors\":2,\"gnss_messages_read\":240,\"last_gnss_message_time\":59750}}}]}",
        ],
        false,
    );
}

/// `raw_rtcm_message_command` (tests/vectors/mip/3dm_streaming.yaml:952)
#[test]
fn case_raw_rtcm_message_command() {
    check(
        "75650c080820664100a0fcc019f4",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":32,\"name\":\"raw_rtcm_message\",\"values\":{\"data\":[102,65,0,160,252,192]}}]}",
        ],
        false,
    );
}

/// `raw_rtcm_message_ack` (tests/vectors/mip/3dm_streaming.yaml:964)
#[test]
fn case_raw_rtcm_message_ack() {
    check(
        "75650c0404f12000ffea",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":32,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `get_base_rate_sensor_command` (tests/vectors/mip/3dm_streaming.yaml:974)
#[test]
fn case_get_base_rate_sensor_command() {
    check(
        "75650c03030e807a7e",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":14,\"name\":\"get_base_rate\",\"values\":{\"desc_set\":128}}]}",
        ],
        false,
    );
}

/// `get_base_rate_sensor_reply` (tests/vectors/mip/3dm_streaming.yaml:983)
#[test]
fn case_get_base_rate_sensor_reply() {
    check(
        "75650c0904f10e00058e8003e8f058",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":14,\"ack_code\":0}},{\"descriptor\":142,\"name\":\"base_rate\",\"values\":{\"desc_set\":128,\"rate\":1000}}]}",
        ],
        false,
    );
}

/// `pps_source_write_generated` (tests/vectors/mip/3dm_streaming.yaml:993)
#[test]
fn case_pps_source_write_generated() {
    check(
        "75650c04042801041b55",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":1,\"source\":4}}]}",
        ],
        false,
    );
}

/// `pps_source_ack` (tests/vectors/mip/3dm_streaming.yaml:1002)
#[test]
fn case_pps_source_ack() {
    check(
        "75650c0404f1280007fa",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `pps_source_save` (tests/vectors/mip/3dm_streaming.yaml:1012)
#[test]
fn case_pps_source_save() {
    check(
        "75650c030328031735",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `pps_source_write_disabled` (tests/vectors/mip/3dm_streaming.yaml:1021)
#[test]
fn case_pps_source_write_disabled() {
    check(
        "75650c04042801001751",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":1,\"source\":0}}]}",
        ],
        false,
    );
}

/// `pps_source_load` (tests/vectors/mip/3dm_streaming.yaml:1030)
#[test]
fn case_pps_source_load() {
    check(
        "75650c030328041836",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `pps_source_load_copy_paste_published` (tests/vectors/mip/3dm_streaming.yaml:1042)
#[test]
fn case_pps_source_load_copy_paste_published() {
    check(
        "75650c0404f128040bfe",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":4}}]}",
        ],
        false,
    );
}

/// `pps_source_default_save_read` (tests/vectors/mip/3dm_streaming.yaml:1060)
#[test]
fn case_pps_source_default_save_read() {
    check(
        "75650c090328050328030328027a4a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":5}},{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":3}},{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `pps_source_default_save_read_reply` (tests/vectors/mip/3dm_streaming.yaml:1071)
#[test]
fn case_pps_source_default_save_read_reply() {
    check(
        "75650c0f04f1280004f1280004f1280003a801f8d9",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}},{\"descriptor\":168,\"name\":\"pps_source_response\",\"values\":{\"source\":1}}]}",
        ],
        false,
    );
}

/// `pps_source_write_gpio` (tests/vectors/mip/3dm_streaming.yaml:1084)
#[test]
fn case_pps_source_write_gpio() {
    check(
        "75650c04042801031a54",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":40,\"name\":\"pps_source\",\"values\":{\"function\":1,\"source\":3}}]}",
        ],
        false,
    );
}

/// `pps_source_read_reply_receiver_2` (tests/vectors/mip/3dm_streaming.yaml:1094)
#[test]
fn case_pps_source_read_reply_receiver_2() {
    check(
        "75650c0704f1280003a802b782",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}},{\"descriptor\":168,\"name\":\"pps_source_response\",\"values\":{\"source\":2}}]}",
        ],
        false,
    );
}

/// `factory_streaming_overwrite` (tests/vectors/mip/3dm_streaming.yaml:1105)
#[test]
fn case_factory_streaming_overwrite() {
    check(
        "75650c0404100000fe07",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":16,\"name\":\"factory_streaming\",\"values\":{\"action\":0,\"reserved\":0}}]}",
        ],
        false,
    );
}

/// `poll_nmea_data_one_sentence` (tests/vectors/mip/3dm_streaming.yaml:1115)
#[test]
fn case_poll_nmea_data_one_sentence() {
    check(
        "75650c0909040001010191000595c3",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":4,\"name\":\"poll_nmea_data\",\"values\":{\"suppress_ack\":false,\"count\":1,\"format_entries\":[{\"message_id\":1,\"talker_id\":1,\"source_desc_set\":145,\"decimation\":5}]}}]}",
        ],
        false,
    );
}

/// `nmea_message_format_write` (tests/vectors/mip/3dm_streaming.yaml:1130)
#[test]
fn case_nmea_message_format_write() {
    check(
        "75650c0e0e0c0102010182000a04029100013732",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":12,\"name\":\"nmea_message_format\",\"values\":{\"function\":1,\"count\":2,\"format_entries\":[{\"message_id\":1,\"talker_id\":1,\"source_desc_set\":130,\"decimation\":10},{\"message_id\":4,\"talker_id\":2,\"source_desc_set\":145,\"decimation\":1}]}}]}",
        ],
        false,
    );
}

/// `nmea_message_format_read` (tests/vectors/mip/3dm_streaming.yaml:1150)
#[test]
fn case_nmea_message_format_read() {
    check(
        "75650c03030c02fafc",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":12,\"name\":\"nmea_message_format\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `nmea_message_format_read_reply` (tests/vectors/mip/3dm_streaming.yaml:1160)
#[test]
fn case_nmea_message_format_read_reply() {
    check(
        "75650c1104f10c000d8c02010182000a0402910001b919",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":12,\"ack_code\":0}},{\"descriptor\":140,\"name\":\"nmea_message_format_response\",\"values\":{\"count\":2,\"format_entries\":[{\"message_id\":1,\"talker_id\":1,\"source_desc_set\":130,\"decimation\":10},{\"message_id\":4,\"talker_id\":2,\"source_desc_set\":145,\"decimation\":1}]}}]}",
        ],
        false,
    );
}

/// `poll_data_sensor_suppress_ack` (tests/vectors/mip/3dm_streaming.yaml:1179)
#[test]
fn case_poll_data_sensor_suppress_ack() {
    check(
        "75650c07070d80010204058db3",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":13,\"name\":\"poll_data\",\"values\":{\"desc_set\":128,\"suppress_ack\":true,\"num_descriptors\":2,\"descriptors\":[4,5]}}]}",
        ],
        false,
    );
}

/// `message_format_write_sensor` (tests/vectors/mip/3dm_streaming.yaml:1191)
#[test]
fn case_message_format_write_sensor() {
    check(
        "75650c0b0b0f01800204000a05000aab00",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":15,\"name\":\"message_format\",\"values\":{\"function\":1,\"desc_set\":128,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":4,\"decimation\":10},{\"descriptor\":5,\"decimation\":10}]}}]}",
        ],
        false,
    );
}

/// `message_format_read_sensor` (tests/vectors/mip/3dm_streaming.yaml:1205)
#[test]
fn case_message_format_read_sensor() {
    check(
        "75650c04040f02807f88",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":15,\"name\":\"message_format\",\"values\":{\"function\":2,\"desc_set\":128}}]}",
        ],
        false,
    );
}

/// `message_format_read_sensor_reply` (tests/vectors/mip/3dm_streaming.yaml:1215)
#[test]
fn case_message_format_read_sensor_reply() {
    check(
        "75650c0e04f10f000a8f800204000a05000a307c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":15,\"ack_code\":0}},{\"descriptor\":143,\"name\":\"message_format_response\",\"values\":{\"desc_set\":128,\"num_descriptors\":2,\"descriptors\":[{\"descriptor\":4,\"decimation\":10},{\"descriptor\":5,\"decimation\":10}]}}]}",
        ],
        false,
    );
}

/// `message_format_save_all` (tests/vectors/mip/3dm_streaming.yaml:1230)
#[test]
fn case_message_format_save_all() {
    check(
        "75650c04040f0300000a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":15,\"name\":\"message_format\",\"values\":{\"function\":3,\"desc_set\":0}}]}",
        ],
        false,
    );
}

/// `factory_streaming_merge` (tests/vectors/mip/3dm_streaming.yaml:1240)
#[test]
fn case_factory_streaming_merge() {
    check(
        "75650c0404100100ff09",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":16,\"name\":\"factory_streaming\",\"values\":{\"action\":1,\"reserved\":0}}]}",
        ],
        false,
    );
}

/// `data_stream_cv7_enable_filter` (tests/vectors/mip/3dm_streaming.yaml:1250)
#[test]
fn case_data_stream_cv7_enable_filter() {
    check(
        "75650c050511018201851c",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"cv7_ins\",\"values\":{\"function\":1,\"desc_set\":130,\"enable\":true}}]}",
        ],
        false,
    );
}

/// `data_stream_cv7_read_filter` (tests/vectors/mip/3dm_streaming.yaml:1261)
#[test]
fn case_data_stream_cv7_read_filter() {
    check(
        "75650c04041102828390",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"cv7_ins\",\"values\":{\"function\":2,\"desc_set\":130}}]}",
        ],
        false,
    );
}

/// `data_stream_cv7_read_filter_reply` (tests/vectors/mip/3dm_streaming.yaml:1272)
#[test]
fn case_data_stream_cv7_read_filter_reply() {
    check(
        "75650c0804f11100048582010054",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}},{\"descriptor\":133,\"name\":\"data_stream_control_response\",\"device\":\"cv7_ins\",\"values\":{\"desc_set\":130,\"enabled\":true}}]}",
        ],
        false,
    );
}

/// `data_stream_cv7_save_all` (tests/vectors/mip/3dm_streaming.yaml:1284)
#[test]
fn case_data_stream_cv7_save_all() {
    check(
        "75650c04041103000210",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"cv7_ins\",\"values\":{\"function\":3,\"desc_set\":0}}]}",
        ],
        false,
    );
}

/// `get_supported_events_triggers` (tests/vectors/mip/3dm_streaming.yaml:1295)
#[test]
fn case_get_supported_events_triggers() {
    check(
        "75650c03032a011737",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":42,\"name\":\"get_supported_events\",\"values\":{\"query\":1}}]}",
        ],
        false,
    );
}

/// `get_supported_events_triggers_reply` (tests/vectors/mip/3dm_streaming.yaml:1305)
#[test]
fn case_get_supported_events_triggers_reply() {
    check(
        "75650c0f04f12a000bb4010c03010402080308fd58",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":42,\"ack_code\":0}},{\"descriptor\":180,\"name\":\"supported_events\",\"values\":{\"query\":1,\"info\":{\"max_instances\":12,\"num_entries\":3,\"entries\":[{\"type\":1,\"count\":4},{\"type\":2,\"count\":8},{\"type\":3,\"count\":8}]}}}]}",
        ],
        false,
    );
}

/// `get_supported_events_actions` (tests/vectors/mip/3dm_streaming.yaml:1327)
#[test]
fn case_get_supported_events_actions() {
    check(
        "75650c03032a021838",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":42,\"name\":\"get_supported_events\",\"values\":{\"query\":2}}]}",
        ],
        false,
    );
}

/// `get_supported_events_actions_reply` (tests/vectors/mip/3dm_streaming.yaml:1337)
#[test]
fn case_get_supported_events_actions_reply() {
    check(
        "75650c0d04f12a0009b4020c0201060208f040",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":42,\"ack_code\":0}},{\"descriptor\":180,\"name\":\"supported_events\",\"values\":{\"query\":2,\"info\":{\"max_instances\":12,\"num_entries\":2,\"entries\":[{\"type\":1,\"count\":6},{\"type\":2,\"count\":8}]}}}]}",
        ],
        false,
    );
}

/// `imu_message_format_read_short` (tests/vectors/mip/3dm_streaming.yaml:1361)
#[test]
fn case_imu_message_format_read_short() {
    check(
        "75650c03030802f6f4",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `imu_message_format_save_short` (tests/vectors/mip/3dm_streaming.yaml:1373)
#[test]
fn case_imu_message_format_save_short() {
    check(
        "75650c03030803f7f5",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":8,\"name\":\"imu_message_format\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `gnss_message_format_read_short` (tests/vectors/mip/3dm_streaming.yaml:1385)
#[test]
fn case_gnss_message_format_read_short() {
    check(
        "75650c03030902f7f6",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":9,\"name\":\"gnss_message_format\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `filter_message_format_read_short` (tests/vectors/mip/3dm_streaming.yaml:1397)
#[test]
fn case_filter_message_format_read_short() {
    check(
        "75650c03030a02f8f8",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":10,\"name\":\"filter_message_format\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `filter_message_format_default_short` (tests/vectors/mip/3dm_streaming.yaml:1409)
#[test]
fn case_filter_message_format_default_short() {
    check(
        "75650c03030a05fbfb",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":10,\"name\":\"filter_message_format\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `data_stream_control_read_short` (tests/vectors/mip/3dm_streaming.yaml:1421)
#[test]
fn case_data_stream_control_read_short() {
    check(
        "75650c0404110201020f",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":17,\"name\":\"data_stream_control\",\"device\":\"gx5_45\",\"values\":{\"function\":2,\"device_selector\":1}}]}",
        ],
        false,
    );
}

/// `gnss_constellation_settings_read_short` (tests/vectors/mip/3dm_streaming.yaml:1434)
#[test]
fn case_gnss_constellation_settings_read_short() {
    check(
        "75650c030321020f26",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":33,\"name\":\"gnss_constellation_settings\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `gnss_assisted_fix_control_read_short` (tests/vectors/mip/3dm_streaming.yaml:1446)
#[test]
fn case_gnss_assisted_fix_control_read_short() {
    check(
        "75650c03032302112a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":35,\"name\":\"gnss_assisted_fix_control\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `gnss_assist_time_update_read_short` (tests/vectors/mip/3dm_streaming.yaml:1458)
#[test]
fn case_gnss_assist_time_update_read_short() {
    check(
        "75650c03032402122c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `frame_config_write_antenna_offset` (tests/vectors/mip/aiding.yaml:13)
#[test]
fn case_frame_config_write_antenna_offset() {
    check(
        "7565131e1e0101010101bea3d70a3de147aebf23d70a00000000000000000000000046a1",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":1,\"name\":\"frame_config\",\"values\":{\"function\":1,\"frame_id\":1,\"format\":1,\"tracking_enabled\":true,\"translation\":[-0.3199999928474426,0.10999999940395355,-0.6399999856948853],\"rotation\":{\"euler\":[0.0,0.0,0.0]}}}]}",
        ],
        false,
    );
}

/// `frame_config_write_notes_example` (tests/vectors/mip/aiding.yaml:38)
#[test]
fn case_frame_config_write_notes_example() {
    check(
        "7565131e1e0101010100000000003f80000000000000000000000000000000000000ecef",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":1,\"name\":\"frame_config\",\"values\":{\"function\":1,\"frame_id\":1,\"format\":1,\"tracking_enabled\":false,\"translation\":[0.0,1.0,0.0],\"rotation\":{\"euler\":[0.0,0.0,0.0]}}}]}",
        ],
        false,
    );
}

/// `frame_config_write_pitch_down` (tests/vectors/mip/aiding.yaml:60)
#[test]
fn case_frame_config_write_pitch_down() {
    check(
        "7565131e1e01010101003f333333000000000000000000000000bfc8f5c300000000448e",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":1,\"name\":\"frame_config\",\"values\":{\"function\":1,\"frame_id\":1,\"format\":1,\"tracking_enabled\":false,\"translation\":[0.699999988079071,0.0,0.0],\"rotation\":{\"euler\":[0.0,-1.5700000524520874,0.0]}}}]}",
        ],
        false,
    );
}

/// `frame_config_write_quaternion` (tests/vectors/mip/aiding.yaml:82)
#[test]
fn case_frame_config_write_quaternion() {
    check(
        "756513222201010202010000000000000000becccccd3f8000000000000000000000000000001a06",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":1,\"name\":\"frame_config\",\"values\":{\"function\":1,\"frame_id\":2,\"format\":2,\"tracking_enabled\":true,\"translation\":[0.0,0.0,-0.4000000059604645],\"rotation\":{\"quaternion\":[1.0,0.0,0.0,0.0]}}}]}",
        ],
        false,
    );
}

/// `frame_config_read_euler` (tests/vectors/mip/aiding.yaml:106)
#[test]
fn case_frame_config_read_euler() {
    check(
        "756513050501020101fc0e",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":1,\"name\":\"frame_config\",\"values\":{\"function\":2,\"frame_id\":1,\"format\":1}}]}",
        ],
        false,
    );
}

/// `frame_config_read_euler_reply` (tests/vectors/mip/aiding.yaml:118)
#[test]
fn case_frame_config_read_euler_reply() {
    check(
        "7565132104f101001d81010101bea3d70a3de147aebf23d70a000000000000000000000000bd93",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"frame_config_response\",\"values\":{\"frame_id\":1,\"format\":1,\"tracking_enabled\":true,\"translation\":[-0.3199999928474426,0.10999999940395355,-0.6399999856948853],\"rotation\":{\"euler\":[0.0,0.0,0.0]}}}]}",
        ],
        false,
    );
}

/// `frame_config_read_quaternion` (tests/vectors/mip/aiding.yaml:140)
#[test]
fn case_frame_config_read_quaternion() {
    check(
        "756513050501020202fe11",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":1,\"name\":\"frame_config\",\"values\":{\"function\":2,\"frame_id\":2,\"format\":2}}]}",
        ],
        false,
    );
}

/// `frame_config_read_quaternion_reply` (tests/vectors/mip/aiding.yaml:150)
#[test]
fn case_frame_config_read_quaternion_reply() {
    check(
        "7565132504f1010021810202010000000000000000becccccd3f3504f300000000000000003f3504f3a89c",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"frame_config_response\",\"values\":{\"frame_id\":2,\"format\":2,\"tracking_enabled\":true,\"translation\":[0.0,0.0,-0.4000000059604645],\"rotation\":{\"quaternion\":[0.7071067690849304,0.0,0.0,0.7071067690849304]}}}]}",
        ],
        false,
    );
}

/// `frame_config_save` (tests/vectors/mip/aiding.yaml:172)
#[test]
fn case_frame_config_save() {
    check(
        "7565130404010301fa0b",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":1,\"name\":\"frame_config\",\"values\":{\"function\":3,\"frame_id\":1}}]}",
        ],
        false,
    );
}

/// `echo_control_write_suppress_ack` (tests/vectors/mip/aiding.yaml:182)
#[test]
fn case_echo_control_write_suppress_ack() {
    check(
        "75651304041f01001560",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":31,\"name\":\"echo_control\",\"values\":{\"function\":1,\"mode\":0}}]}",
        ],
        false,
    );
}

/// `echo_control_write_response` (tests/vectors/mip/aiding.yaml:192)
#[test]
fn case_echo_control_write_response() {
    check(
        "75651304041f01021762",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":31,\"name\":\"echo_control\",\"values\":{\"function\":1,\"mode\":2}}]}",
        ],
        false,
    );
}

/// `echo_control_read` (tests/vectors/mip/aiding.yaml:202)
#[test]
fn case_echo_control_read() {
    check(
        "75651303031f021445",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":31,\"name\":\"echo_control\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `echo_control_read_reply` (tests/vectors/mip/aiding.yaml:212)
#[test]
fn case_echo_control_read_reply() {
    check(
        "7565130704f11f00039f01ab81",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":31,\"ack_code\":0}},{\"descriptor\":159,\"name\":\"echo_control_response\",\"values\":{\"mode\":1}}]}",
        ],
        false,
    );
}

/// `echo_control_default` (tests/vectors/mip/aiding.yaml:224)
#[test]
fn case_echo_control_default() {
    check(
        "75651303031f051748",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":31,\"name\":\"echo_control\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `ecef_position_measurement` (tests/vectors/mip/aiding.yaml:234)
#[test]
fn case_ecef_position_measurement() {
    check(
        "7565133333210200112210f47de9811501412e848100000000c151edd810000000414f47d010000000402000004020000040a0000000076337",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":33,\"name\":\"ecef_position\",\"values\":{\"time\":{\"timebase\":2,\"reserved\":0,\"nanoseconds\":1234567890123456789},\"frame_id\":1,\"position\":[1000000.5,-4700000.25,4100000.125],\"uncertainty\":[2.5,2.5,5.0],\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `llh_position_measurement` (tests/vectors/mip/aiding.yaml:260)
#[test]
fn case_llh_position_measurement() {
    check(
        "7565133333220200136dcc951d8c0000014046380000000000c052440000000000405e2000000000003fc000003fc000004040000000075911",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":34,\"name\":\"llh_position\",\"values\":{\"time\":{\"timebase\":2,\"reserved\":0,\"nanoseconds\":1400000000000000000},\"frame_id\":1,\"latitude\":44.4375,\"longitude\":-73.0625,\"height\":120.5,\"uncertainty\":[1.5,1.5,3.0],\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `llh_position_height_only` (tests/vectors/mip/aiding.yaml:287)
#[test]
fn case_llh_position_height_only() {
    check(
        "75651333332201000000000df84758000100000000000000000000000000000000405e20000000000000000000000000004040000000045dfd",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":34,\"name\":\"llh_position\",\"values\":{\"time\":{\"timebase\":1,\"reserved\":0,\"nanoseconds\":60000000000},\"frame_id\":1,\"latitude\":0.0,\"longitude\":0.0,\"height\":120.5,\"uncertainty\":[0.0,0.0,3.0],\"valid_flags\":4}}]}",
        ],
        false,
    );
}

/// `height_above_ellipsoid_measurement` (tests/vectors/mip/aiding.yaml:314)
#[test]
fn case_height_above_ellipsoid_measurement() {
    check(
        "7565131717230100000000012a05f20001437a4000400000000001a04e",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":35,\"name\":\"height_above_ellipsoid\",\"values\":{\"time\":{\"timebase\":1,\"reserved\":0,\"nanoseconds\":5000000000},\"frame_id\":1,\"height\":250.25,\"uncertainty\":2.0,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `ecef_velocity_measurement` (tests/vectors/mip/aiding.yaml:335)
#[test]
fn case_ecef_velocity_measurement() {
    check(
        "7565132727280200136dcc953b596500013fc00000be800000000000003dcccccd3dcccccd3dcccccd00076a41",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":40,\"name\":\"ecef_velocity\",\"values\":{\"time\":{\"timebase\":2,\"reserved\":0,\"nanoseconds\":1400000000500000000},\"frame_id\":1,\"velocity\":[1.5,-0.25,0.0],\"uncertainty\":[0.10000000149011612,0.10000000149011612,0.10000000149011612],\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `ned_velocity_measurement_time_of_arrival` (tests/vectors/mip/aiding.yaml:356)
#[test]
fn case_ned_velocity_measurement_time_of_arrival() {
    check(
        "756513272729030000000000000000000141200000c02000003e0000003d4ccccd3d4ccccd3dcccccd0003d0c1",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":41,\"name\":\"ned_velocity\",\"values\":{\"time\":{\"timebase\":3,\"reserved\":0,\"nanoseconds\":0},\"frame_id\":1,\"velocity\":[10.0,-2.5,0.125],\"uncertainty\":[0.05000000074505806,0.05000000074505806,0.10000000149011612],\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `body_frame_velocity_example` (tests/vectors/mip/aiding.yaml:377)
#[test]
fn case_body_frame_velocity_example() {
    check(
        "75651327272a0100000000000002693002406fae1400000000000000003df5c28f3df5c28f3df5c28f000300a3",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":42,\"name\":\"body_frame_velocity\",\"values\":{\"time\":{\"timebase\":1,\"reserved\":0,\"nanoseconds\":158000},\"frame_id\":2,\"velocity\":[3.744999885559082,0.0,0.0],\"uncertainty\":[0.11999999731779099,0.11999999731779099,0.11999999731779099],\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `body_frame_velocity_nack_invalid_parameter` (tests/vectors/mip/aiding.yaml:403)
#[test]
fn case_body_frame_velocity_nack_invalid_parameter() {
    check(
        "7565130404f12a03132b",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":42,\"ack_code\":3}}]}",
        ],
        false,
    );
}

/// `true_heading_measurement` (tests/vectors/mip/aiding.yaml:415)
#[test]
fn case_true_heading_measurement() {
    check(
        "75651317173101000000000077359400013fc90fdb3c8f5c290001d181",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":49,\"name\":\"true_heading\",\"values\":{\"time\":{\"timebase\":1,\"reserved\":0,\"nanoseconds\":2000000000},\"frame_id\":1,\"heading\":1.5707963705062866,\"uncertainty\":0.017500000074505806,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `magnetic_field_example` (tests/vectors/mip/aiding.yaml:435)
#[test]
fn case_magnetic_field_example() {
    check(
        "75651327273201000000000000026930033ee6e9793eb0a3d73ecd4fdf3cfdf3b63cfdf3b63cfdf3b60007e0ec",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":50,\"name\":\"magnetic_field\",\"values\":{\"time\":{\"timebase\":1,\"reserved\":0,\"nanoseconds\":158000},\"frame_id\":3,\"magnetic_field\":[0.45100000500679016,0.3449999988079071,0.4009999930858612],\"uncertainty\":[0.03099999949336052,0.03099999949336052,0.03099999949336052],\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `magnetic_field_ack` (tests/vectors/mip/aiding.yaml:459)
#[test]
fn case_magnetic_field_ack() {
    check(
        "7565130404f132001838",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":50,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `pressure_measurement` (tests/vectors/mip/aiding.yaml:469)
#[test]
fn case_pressure_measurement() {
    check(
        "756513171733010000000000b2d05e0000447d50003f000000000180c0",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":51,\"name\":\"pressure\",\"values\":{\"time\":{\"timebase\":1,\"reserved\":0,\"nanoseconds\":3000000000},\"frame_id\":0,\"pressure\":1013.25,\"uncertainty\":0.5,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `llh_position_and_ned_velocity_one_packet` (tests/vectors/mip/aiding.yaml:489)
#[test]
fn case_llh_position_and_ned_velocity_one_packet() {
    check(
        "7565135a33220200136dcc951d8c0000014046380000000000c052440000000000405e2000000000003fc000003fc0000040400000000727290200136dcc951d8c00000141200000c02000003e0000003d4ccccd3d4ccccd3dcccccd0007c9ab",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":34,\"name\":\"llh_position\",\"values\":{\"time\":{\"timebase\":2,\"reserved\":0,\"nanoseconds\":1400000000000000000},\"frame_id\":1,\"latitude\":44.4375,\"longitude\":-73.0625,\"height\":120.5,\"uncertainty\":[1.5,1.5,3.0],\"valid_flags\":7}},{\"descriptor\":41,\"name\":\"ned_velocity\",\"values\":{\"time\":{\"timebase\":2,\"reserved\":0,\"nanoseconds\":1400000000000000000},\"frame_id\":1,\"velocity\":[10.0,-2.5,0.125],\"uncertainty\":[0.05000000074505806,0.05000000074505806,0.10000000149011612],\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `llh_position_and_ned_velocity_acks` (tests/vectors/mip/aiding.yaml:526)
#[test]
fn case_llh_position_and_ned_velocity_acks() {
    check(
        "7565130804f1220004f129002a91",
        None,
        &[
            "{\"offset\":0,\"set\":19,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":34,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":41,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `ping_command` (tests/vectors/mip/base.yaml:8)
#[test]
fn case_ping_command() {
    check(
        "756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `ping_reply` (tests/vectors/mip/base.yaml:19)
#[test]
fn case_ping_reply() {
    check(
        "7565010404f10100d56a",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `set_to_idle_command` (tests/vectors/mip/base.yaml:30)
#[test]
fn case_set_to_idle_command() {
    check(
        "756501020202e1c7",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `set_to_idle_copy_paste_published` (tests/vectors/mip/base.yaml:40)
#[test]
fn case_set_to_idle_copy_paste_published() {
    check(
        "756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `set_to_idle_reply` (tests/vectors/mip/base.yaml:56)
#[test]
fn case_set_to_idle_reply() {
    check(
        "7565010404f10200d66c",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":2,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `get_device_info_command` (tests/vectors/mip/base.yaml:66)
#[test]
fn case_get_device_info_command() {
    check(
        "756501020203e2c8",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"get_device_info\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_device_info_reply` (tests/vectors/mip/base.yaml:75)
#[test]
fn case_get_device_info_reply() {
    check(
        "7565015804f10300548105fe33444d2d4758352d3435202020202020363233322d3432373020202020202020363233322d30303132322020202020202020202020202020202020202020202035672c20313530642f73202020202020b801",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":3,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"device_info\",\"values\":{\"info\":{\"firmware_version\":1534,\"model_name\":\"3DM-GX5-45      \",\"model_number\":\"6232-4270       \",\"serial_number\":\"6232-00122      \",\"lot_number\":\"                \",\"device_options\":\"5g, 150d/s      \"}}}]}",
        ],
        false,
    );
}

/// `get_device_descriptors_command` (tests/vectors/mip/base.yaml:107)
#[test]
fn case_get_device_descriptors_command() {
    check(
        "756501020204e3c9",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"get_device_descriptors\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_device_descriptors_reply` (tests/vectors/mip/base.yaml:116)
#[test]
fn case_get_device_descriptors_reply() {
    check(
        "7565011204f104000e820101010201030c010c020c721805",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":4,\"ack_code\":0}},{\"descriptor\":130,\"name\":\"device_descriptors\",\"values\":{\"descriptors\":[257,258,259,3073,3074,3186]}}]}",
        ],
        false,
    );
}

/// `get_device_descriptors_reply_empty` (tests/vectors/mip/base.yaml:131)
#[test]
fn case_get_device_descriptors_reply_empty() {
    check(
        "7565010604f1040002825eb4",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":4,\"ack_code\":0}},{\"descriptor\":130,\"name\":\"device_descriptors\",\"values\":{\"descriptors\":[]}}]}",
        ],
        false,
    );
}

/// `built_in_test_command` (tests/vectors/mip/base.yaml:142)
#[test]
fn case_built_in_test_command() {
    check(
        "756501020205e4ca",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"built_in_test\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `built_in_test_reply` (tests/vectors/mip/base.yaml:151)
#[test]
fn case_built_in_test_reply() {
    check(
        "7565010a04f10500068300000000687d",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":5,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"built_in_test_result\",\"device\":\"gx5_45\",\"values\":{\"flags\":0}}]}",
        ],
        false,
    );
}

/// `built_in_test_reply_gx5_flags` (tests/vectors/mip/base.yaml:161)
#[test]
fn case_built_in_test_reply_gx5_flags() {
    check(
        "7565010a04f105000683010003016d88",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":5,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"built_in_test_result\",\"device\":\"gx5_45\",\"values\":{\"flags\":16777985}}]}",
        ],
        false,
    );
}

/// `resume_command` (tests/vectors/mip/base.yaml:177)
#[test]
fn case_resume_command() {
    check(
        "756501020206e5cb",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":6,\"name\":\"resume\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `resume_reply` (tests/vectors/mip/base.yaml:187)
#[test]
fn case_resume_reply() {
    check(
        "7565010404f10600da74",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":6,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `resume_reply_table_published` (tests/vectors/mip/base.yaml:196)
#[test]
fn case_resume_reply_table_published() {
    check(
        "7565010404f10100da74",
        None,
        &["{\"offset\":0,\"skipped\":\"7565010404f10100da74\"}"],
        true,
    );
}

/// `get_extended_descriptors_command` (tests/vectors/mip/base.yaml:209)
#[test]
fn case_get_extended_descriptors_command() {
    check(
        "756501020207e6cc",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":7,\"name\":\"get_extended_descriptors\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `get_extended_descriptors_table_published` (tests/vectors/mip/base.yaml:218)
#[test]
fn case_get_extended_descriptors_table_published() {
    check(
        "756501020204e6cc",
        None,
        &["{\"offset\":0,\"skipped\":\"756501020204e6cc\"}"],
        true,
    );
}

/// `get_extended_descriptors_reply` (tests/vectors/mip/base.yaml:231)
#[test]
fn case_get_extended_descriptors_reply() {
    check(
        "7565010e04f107000a860d270d28822b822c39fc",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":7,\"ack_code\":0}},{\"descriptor\":134,\"name\":\"extended_descriptors\",\"values\":{\"descriptors\":[3367,3368,33323,33324]}}]}",
        ],
        false,
    );
}

/// `continuous_bit_command` (tests/vectors/mip/base.yaml:245)
#[test]
fn case_continuous_bit_command() {
    check(
        "756501020208e7cd",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":8,\"name\":\"continuous_bit\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `continuous_bit_reply` (tests/vectors/mip/base.yaml:255)
#[test]
fn case_continuous_bit_reply() {
    check(
        "7565011604f108001288000102030405060708090a0b0c0d0e0f0082",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":8,\"ack_code\":0}},{\"descriptor\":136,\"name\":\"continuous_bit_result\",\"values\":{\"result\":{\"system_byte_0\":0,\"reserved_byte_1\":1,\"system_byte_2\":2,\"system_byte_3\":3,\"imu_byte_4\":4,\"imu_byte_5\":5,\"imu_byte_6\":6,\"imu_byte_7\":7,\"nav_byte_8\":8,\"reserved_byte_9\":9,\"reserved_byte_10\":10,\"reserved_byte_11\":11,\"reserved_byte_12\":12,\"gnss_byte_13\":13,\"gnss_byte_14\":14,\"reserved_byte_15\":15}}}]}",
        ],
        false,
    );
}

/// `comm_port_speed_write` (tests/vectors/mip/base.yaml:292)
#[test]
fn case_comm_port_speed_write() {
    check(
        "75650108080901010001c200b936",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"comm_port_speed\",\"values\":{\"function\":1,\"port\":1,\"baud\":115200}}]}",
        ],
        false,
    );
}

/// `comm_port_speed_read` (tests/vectors/mip/base.yaml:304)
#[test]
fn case_comm_port_speed_read() {
    check(
        "7565010404090201efb5",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"comm_port_speed\",\"values\":{\"function\":2,\"port\":1}}]}",
        ],
        false,
    );
}

/// `comm_port_speed_save_all` (tests/vectors/mip/base.yaml:315)
#[test]
fn case_comm_port_speed_save_all() {
    check(
        "7565010404090300efb6",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"comm_port_speed\",\"values\":{\"function\":3,\"port\":0}}]}",
        ],
        false,
    );
}

/// `comm_port_speed_read_reply` (tests/vectors/mip/base.yaml:325)
#[test]
fn case_comm_port_speed_read_reply() {
    check(
        "7565010b04f10900078901000e1000938f",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":9,\"ack_code\":0}},{\"descriptor\":137,\"name\":\"comm_port_speed_response\",\"values\":{\"port\":1,\"baud\":921600}}]}",
        ],
        false,
    );
}

/// `gps_time_update_write_week` (tests/vectors/mip/base.yaml:338)
#[test]
fn case_gps_time_update_write_week() {
    check(
        "756501080872010100000698fd32",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\",\"device\":\"gx5_45\",\"values\":{\"function\":1,\"field_id\":1,\"value\":1688}}]}",
        ],
        false,
    );
}

/// `gps_time_update_table_published` (tests/vectors/mip/base.yaml:347)
#[test]
fn case_gps_time_update_table_published() {
    check(
        "756501080872010000000698fd32",
        None,
        &["{\"offset\":0,\"skipped\":\"756501080872010000000698fd32\"}"],
        true,
    );
}

/// `gps_time_update_reply` (tests/vectors/mip/base.yaml:360)
#[test]
fn case_gps_time_update_reply() {
    check(
        "7565010404f17200464c",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":114,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gps_time_update_read_week` (tests/vectors/mip/base.yaml:369)
#[test]
fn case_gps_time_update_read_week() {
    check(
        "756501040472020158f0",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\",\"device\":\"gx5_45\",\"values\":{\"function\":2,\"field_id\":1}}]}",
        ],
        false,
    );
}

/// `gps_week_reply` (tests/vectors/mip/base.yaml:381)
#[test]
fn case_gps_week_reply() {
    check(
        "7565010a04f17200068400000698748e",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":114,\"ack_code\":0}},{\"descriptor\":132,\"name\":\"gps_week\",\"values\":{\"week\":1688}}]}",
        ],
        false,
    );
}

/// `gps_seconds_reply` (tests/vectors/mip/base.yaml:394)
#[test]
fn case_gps_seconds_reply() {
    check(
        "7565010a04f17200068500054600228a",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":114,\"ack_code\":0}},{\"descriptor\":133,\"name\":\"gps_seconds\",\"values\":{\"seconds\":345600}}]}",
        ],
        false,
    );
}

/// `gps_time_update_write_no_ack` (tests/vectors/mip/base.yaml:407)
#[test]
fn case_gps_time_update_write_no_ack() {
    check(
        "756501080872060200054600b04c",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\",\"device\":\"gx5_45\",\"values\":{\"function\":6,\"field_id\":2,\"value\":345600}}]}",
        ],
        false,
    );
}

/// `device_reset_command` (tests/vectors/mip/base.yaml:419)
#[test]
fn case_device_reset_command() {
    check(
        "75650102027e5d43",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":126,\"name\":\"device_reset\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `device_reset_reply` (tests/vectors/mip/base.yaml:428)
#[test]
fn case_device_reset_reply() {
    check(
        "7565010404f17e005264",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":126,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `nack_invalid_parameter` (tests/vectors/mip/base.yaml:437)
#[test]
fn case_nack_invalid_parameter() {
    check(
        "7565010404f17e035567",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":126,\"ack_code\":3}}]}",
        ],
        false,
    );
}

/// `two_commands_one_packet` (tests/vectors/mip/base.yaml:448)
#[test]
fn case_two_commands_one_packet() {
    check(
        "7565010402010202e696",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}},{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `gps_time_update_write_week_cv7` (tests/vectors/mip/base.yaml:461)
#[test]
fn case_gps_time_update_write_week_cv7() {
    check(
        "756501080872010100000698fd32",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\",\"device\":\"cv7_ins\",\"values\":{\"function\":1,\"field_id\":1,\"value\":1688}}]}",
        ],
        false,
    );
}

/// `built_in_test_reply_cv7_flags` (tests/vectors/mip/base.yaml:475)
#[test]
fn case_built_in_test_reply_cv7_flags() {
    check(
        "7565010a04f10500068300802000083d",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":5,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"built_in_test_result\",\"device\":\"cv7_ins\",\"values\":{\"flags\":8396800}}]}",
        ],
        false,
    );
}

/// `device_info_every_string_byte` (tests/vectors/mip/base.yaml:489)
#[test]
fn case_device_info_every_string_byte() {
    check(
        "756501545481ffff5122425c00011f7f80ff7e20090a0d5a0000000000000000000000000000000020202020202020202020202020202020202122232425262728292a2b2c2d2e2ff0f1f2f3f4f5f6f7f8f9fafbfcfdfeff39e6",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":129,\"name\":\"device_info\",\"values\":{\"info\":{\"firmware_version\":65535,\"model_name\":\"Q\\\"B\\\\\\u0000\\u0001\\u001f\\u007f\\u0080\\u00ff~ \\u0009\\u000a\\u000dZ\",\"model_number\":\"\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\",\"serial_number\":\"                \",\"lot_number\":\" !\\\"#$%&'()*+,-./\",\"device_options\":\"\\u00f0\\u00f1\\u00f2\\u00f3\\u00f4\\u00f5\\u00f6\\u00f7\\u00f8\\u00f9\\u00fa\\u00fb\\u00fc\\u00fd\\u00fe\\u00ff\"}}}]}",
        ],
        false,
    );
}

/// `encode_input_float_rounding` (tests/vectors/mip/encode_input.yaml:10)
#[test]
fn case_encode_input_float_rounding() {
    check(
        "75650c11112401000000000000000000003f800000ec7f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":1,\"tow\":0.0,\"week_number\":0,\"accuracy\":1.0}}]}",
        ],
        false,
    );
}

/// `encode_input_float_range` (tests/vectors/mip/encode_input.yaml:49)
#[test]
fn case_encode_input_float_range() {
    check(
        "75650c11112401000000000000000000007f7fffff2979",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":1,\"tow\":0.0,\"week_number\":0,\"accuracy\":3.4028234663852886e+38}}]}",
        ],
        false,
    );
}

/// `encode_input_double_range` (tests/vectors/mip/encode_input.yaml:77)
#[test]
fn case_encode_input_double_range() {
    check(
        "75650c1111240100000000000000000000000000002d03",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":1,\"tow\":0.0,\"week_number\":0,\"accuracy\":0.0}}]}",
        ],
        false,
    );
}

/// `encode_input_negative_zero` (tests/vectors/mip/encode_input.yaml:104)
#[test]
fn case_encode_input_negative_zero() {
    check(
        "75650c1111240180000000000000000000800000002d03",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":1,\"tow\":-0.0,\"week_number\":0,\"accuracy\":-0.0}}]}",
        ],
        false,
    );
}

/// `encode_input_denormals` (tests/vectors/mip/encode_input.yaml:124)
#[test]
fn case_encode_input_denormals() {
    check(
        "75650c1111240100000000000000010000000000012f0b",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":1,\"tow\":5e-324,\"week_number\":0,\"accuracy\":1.401298464324817e-45}}]}",
        ],
        false,
    );
}

/// `encode_input_nan_text` (tests/vectors/mip/encode_input.yaml:142)
#[test]
fn case_encode_input_nan_text() {
    check(
        "75650c11112401fff000000000000100007fc000015d69",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":36,\"name\":\"gnss_assist_time_update\",\"values\":{\"function\":1,\"tow\":\"nan:0xfff0000000000001\",\"week_number\":0,\"accuracy\":\"nan:0x7fc00001\"}}]}",
        ],
        false,
    );
}

/// `encode_input_packet_keys` (tests/vectors/mip/encode_input.yaml:169)
#[test]
fn case_encode_input_packet_keys() {
    check(
        "75650c0504c8abcd013087",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":200,\"data\":\"abcd\",\"error\":\"unknown descriptor\"},{\"trailing\":\"01\",\"error\":\"field header at payload offset 4 needs 2 bytes, 1 left\"}]}",
        ],
        false,
    );
}

/// `encode_input_field_keys` (tests/vectors/mip/encode_input.yaml:207)
#[test]
fn case_encode_input_field_keys() {
    check(
        "756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `event_trigger_gpio_edge` (tests/vectors/mip/events.yaml:6)
#[test]
fn case_event_trigger_gpio_edge() {
    check(
        "75650c07072e01010101042af4",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":1,\"type\":1,\"parameters\":{\"pin\":1,\"mode\":4}}}]}",
        ],
        false,
    );
}

/// `event_action_message_sensor` (tests/vectors/mip/events.yaml:16)
#[test]
fn case_event_action_message_sensor() {
    check(
        "75650c0f0f2f0101010280000005d0d5d6070847ca",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_set\":128,\"decimation\":0,\"num_fields\":5,\"descriptors\":[208,213,214,7,8]}}}]}",
        ],
        false,
    );
}

/// `event_action_message_filter` (tests/vectors/mip/events.yaml:31)
#[test]
fn case_event_action_message_filter() {
    check(
        "75650c0e0e2f0102010282000004d0d5d6053d7a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":2,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_set\":130,\"decimation\":0,\"num_fields\":4,\"descriptors\":[208,213,214,5]}}}]}",
        ],
        false,
    );
}

/// `event_control_enable_1` (tests/vectors/mip/events.yaml:46)
#[test]
fn case_event_control_enable_1() {
    check(
        "75650c05052b0101011e82",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":43,\"name\":\"event_control\",\"values\":{\"function\":1,\"instance\":1,\"mode\":1}}]}",
        ],
        false,
    );
}

/// `event_action_gpio_active_high` (tests/vectors/mip/events.yaml:58)
#[test]
fn case_event_action_gpio_active_high() {
    check(
        "75650c08082f0101010101012b31",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":1,\"parameters\":{\"pin\":1,\"mode\":1}}}]}",
        ],
        false,
    );
}

/// `event_trigger_threshold_interval` (tests/vectors/mip/events.yaml:68)
#[test]
fn case_event_trigger_threshold_interval() {
    check(
        "75650c19192e01010280d50102415fca0540000000416fca0560000000308a",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":1,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":213,\"param_id\":1,\"type\":2,\"low_thres\":8333333.0,\"high_thres\":16666667.0}}}]}",
        ],
        false,
    );
}

/// `event_trigger_gpio_while_low` (tests/vectors/mip/events.yaml:85)
#[test]
fn case_event_trigger_gpio_while_low() {
    check(
        "75650c07072e01010103022af6",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":1,\"type\":1,\"parameters\":{\"pin\":3,\"mode\":2}}}]}",
        ],
        false,
    );
}

/// `get_event_trigger_status_1` (tests/vectors/mip/events.yaml:95)
#[test]
fn case_get_event_trigger_status_1() {
    check(
        "75650c04042c01011c5e",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":44,\"name\":\"get_event_trigger_status\",\"values\":{\"requested_count\":1,\"requested_instances\":[1]}}]}",
        ],
        false,
    );
}

/// `event_trigger_status_enabled` (tests/vectors/mip/events.yaml:103)
#[test]
fn case_event_trigger_status_enabled() {
    check(
        "75650c0904f12c0005b6010102cf63",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":44,\"ack_code\":0}},{\"descriptor\":182,\"name\":\"event_trigger_status\",\"values\":{\"count\":1,\"triggers\":[{\"type\":1,\"status\":2}]}}]}",
        ],
        false,
    );
}

/// `event_trigger_status_active` (tests/vectors/mip/events.yaml:119)
#[test]
fn case_event_trigger_status_active() {
    check(
        "75650c0904f12c0005b6010103d064",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":44,\"ack_code\":0}},{\"descriptor\":182,\"name\":\"event_trigger_status\",\"values\":{\"count\":1,\"triggers\":[{\"type\":1,\"status\":3}]}}]}",
        ],
        false,
    );
}

/// `event_action_message_decimated_sensor` (tests/vectors/mip/events.yaml:128)
#[test]
fn case_event_action_message_decimated_sensor() {
    check(
        "75650c0c0c2f0101010280000a020405c778",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_set\":128,\"decimation\":10,\"num_fields\":2,\"descriptors\":[4,5]}}}]}",
        ],
        false,
    );
}

/// `event_action_message_decimated_filter` (tests/vectors/mip/events.yaml:143)
#[test]
fn case_event_action_message_decimated_filter() {
    check(
        "75650c0b0b2f0102010282000a0105c3ab",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":2,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_set\":130,\"decimation\":10,\"num_fields\":1,\"descriptors\":[5]}}}]}",
        ],
        false,
    );
}

/// `event_action_gpio_oneshot_high` (tests/vectors/mip/events.yaml:158)
#[test]
fn case_event_action_gpio_oneshot_high() {
    check(
        "75650c08082f010101010405323b",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":1,\"parameters\":{\"pin\":4,\"mode\":5}}}]}",
        ],
        false,
    );
}

/// `event_trigger_threshold_roll_45` (tests/vectors/mip/events.yaml:168)
#[test]
fn case_event_trigger_threshold_roll_45() {
    check(
        "75650c19192e010102800c01013fe921fb323ae5afbfe921fb323ae5afe040",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":1,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":0.7853981,\"high_thres\":-0.7853981}}}]}",
        ],
        false,
    );
}

/// `event_trigger_threshold_pitch_45` (tests/vectors/mip/events.yaml:182)
#[test]
fn case_event_trigger_threshold_pitch_45() {
    check(
        "75650c19192e010202800c02013fe921fb323ae5afbfe921fb323ae5afe268",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":2,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":2,\"type\":1,\"low_thres\":0.7853981,\"high_thres\":-0.7853981}}}]}",
        ],
        false,
    );
}

/// `event_control_enable_2` (tests/vectors/mip/events.yaml:196)
#[test]
fn case_event_control_enable_2() {
    check(
        "75650c05052b0102011f84",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":43,\"name\":\"event_control\",\"values\":{\"function\":1,\"instance\":2,\"mode\":1}}]}",
        ],
        false,
    );
}

/// `event_trigger_combination_any` (tests/vectors/mip/events.yaml:207)
#[test]
fn case_event_trigger_combination_any() {
    check(
        "75650c0b0b2e010303fffe0102000031f6",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":3,\"type\":3,\"parameters\":{\"logic_table\":65534,\"input_triggers\":[1,2,0,0]}}}]}",
        ],
        false,
    );
}

/// `event_control_enable_3` (tests/vectors/mip/events.yaml:229)
#[test]
fn case_event_control_enable_3() {
    check(
        "75650c05052b0103012086",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":43,\"name\":\"event_control\",\"values\":{\"function\":1,\"instance\":3,\"mode\":1}}]}",
        ],
        false,
    );
}

/// `event_action_gpio_trigger_3` (tests/vectors/mip/events.yaml:239)
#[test]
fn case_event_action_gpio_trigger_3() {
    check(
        "75650c08082f010103010401303f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":1,\"trigger\":3,\"type\":1,\"parameters\":{\"pin\":4,\"mode\":1}}}]}",
        ],
        false,
    );
}

/// `event_action_gpio_oneshot_trigger_3` (tests/vectors/mip/events.yaml:250)
#[test]
fn case_event_action_gpio_oneshot_trigger_3() {
    check(
        "75650c08082f0101030104053443",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":1,\"trigger\":3,\"type\":1,\"parameters\":{\"pin\":4,\"mode\":5}}}]}",
        ],
        false,
    );
}

/// `event_action_gpio_oneshot_trigger_3_published` (tests/vectors/mip/events.yaml:266)
#[test]
fn case_event_action_gpio_oneshot_trigger_3_published() {
    check(
        "75650c08082f010103010401303f",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":1,\"trigger\":3,\"type\":1,\"parameters\":{\"pin\":4,\"mode\":1}}}]}",
        ],
        false,
    );
}

/// `event_trigger_threshold_roll_10` (tests/vectors/mip/events.yaml:287)
#[test]
fn case_event_trigger_threshold_roll_10() {
    check(
        "75650c19192e010202800c0101bfc6571814c9bba03fc6571814c9bba0b1fa",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":2,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":-0.1745329,\"high_thres\":0.1745329}}}]}",
        ],
        false,
    );
}

/// `event_trigger_combination_latch` (tests/vectors/mip/events.yaml:303)
#[test]
fn case_event_trigger_combination_latch() {
    check(
        "75650c0b0b2e010303cece03010200d3e9",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":3,\"type\":3,\"parameters\":{\"logic_table\":52942,\"input_triggers\":[3,1,2,0]}}}]}",
        ],
        false,
    );
}

/// `event_action_gpio_oneshot_low` (tests/vectors/mip/events.yaml:313)
#[test]
fn case_event_action_gpio_oneshot_low() {
    check(
        "75650c08082f0102020104063545",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\",\"values\":{\"function\":1,\"instance\":2,\"trigger\":2,\"type\":1,\"parameters\":{\"pin\":4,\"mode\":6}}}]}",
        ],
        false,
    );
}

/// `event_trigger_config_read` (tests/vectors/mip/events.yaml:323)
#[test]
fn case_event_trigger_config_read() {
    check(
        "75650c04042e02011f66",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":2,\"instance\":1}}]}",
        ],
        false,
    );
}

/// `event_trigger_config_read_reply_none` (tests/vectors/mip/events.yaml:334)
#[test]
fn case_event_trigger_config_read_reply_none() {
    check(
        "75650c0804f12e0004b80100ce98",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":46,\"ack_code\":0}},{\"descriptor\":184,\"name\":\"event_trigger_config_response\",\"values\":{\"instance\":1,\"type\":0,\"parameters\":null}}]}",
        ],
        false,
    );
}

/// `get_event_action_status_all_reply` (tests/vectors/mip/events.yaml:347)
#[test]
fn case_get_event_action_status_all_reply() {
    check(
        "75650c0b04f12d0007b70202010103da41",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":45,\"ack_code\":0}},{\"descriptor\":183,\"name\":\"event_action_status\",\"values\":{\"count\":2,\"actions\":[{\"action_type\":2,\"trigger_id\":1},{\"action_type\":1,\"trigger_id\":3}]}}]}",
        ],
        false,
    );
}

/// `doubles_power_of_two_and_negative_zero` (tests/vectors/mip/events.yaml:365)
#[test]
fn case_doubles_power_of_two_and_negative_zero() {
    check(
        "75650c19192e010402800c010116900000000000008000000000000000014c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":5.225680706521042e-200,\"high_thres\":-0.0}}}]}",
        ],
        false,
    );
}

/// `doubles_denormal_and_1e16` (tests/vectors/mip/events.yaml:379)
#[test]
fn case_doubles_denormal_and_1e16() {
    check(
        "75650c19192e010402800c010100000000000000014341c37937e0800033cf",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":5e-324,\"high_thres\":1e+16}}}]}",
        ],
        false,
    );
}

/// `doubles_positional_boundary` (tests/vectors/mip/events.yaml:390)
#[test]
fn case_doubles_positional_boundary() {
    check(
        "75650c19192e010402800c01013f1a36e2eb1c432d3ee4f8b588e368f156da",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":0.0001,\"high_thres\":1e-05}}}]}",
        ],
        false,
    );
}

/// `doubles_large_values` (tests/vectors/mip/events.yaml:401)
#[test]
fn case_doubles_large_values() {
    check(
        "75650c19192e010402800c01017e37e43c8800759c42dc12218377de6bdd44",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":1e+300,\"high_thres\":123456789012345.67}}}]}",
        ],
        false,
    );
}

/// `doubles_infinity_and_nan_payload` (tests/vectors/mip/events.yaml:412)
#[test]
fn case_doubles_infinity_and_nan_payload() {
    check(
        "75650c19192e010402800c01017ff0000000000000fff00000000000013a05",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\",\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":\"inf\",\"high_thres\":\"nan:0xfff0000000000001\"}}}]}",
        ],
        false,
    );
}

/// `reset_filter_command` (tests/vectors/mip/filter_01_1f.yaml:10)
#[test]
fn case_reset_filter_command() {
    check(
        "75650d020201ecf6",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":1,\"name\":\"reset_filter\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `reset_filter_reply` (tests/vectors/mip/filter_01_1f.yaml:20)
#[test]
fn case_reset_filter_reply() {
    check(
        "75650d0404f10100e1b2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `reset_and_run_filter_one_packet` (tests/vectors/mip/filter_01_1f.yaml:28)
#[test]
fn case_reset_and_run_filter_one_packet() {
    check(
        "75650d0402010205f5e1",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":1,\"name\":\"reset_filter\",\"values\":{}},{\"descriptor\":5,\"name\":\"run_filter\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `set_initial_attitude_zero` (tests/vectors/mip/filter_01_1f.yaml:43)
#[test]
fn case_set_initial_attitude_zero() {
    check(
        "75650d0e0e02000000000000000000000000056f",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":2,\"name\":\"set_initial_attitude\",\"values\":{\"roll\":0.0,\"pitch\":0.0,\"heading\":0.0}}]}",
        ],
        false,
    );
}

/// `set_initial_attitude_copy_paste_published` (tests/vectors/mip/filter_01_1f.yaml:51)
#[test]
fn case_set_initial_attitude_copy_paste_published() {
    check(
        "75650d0e0e020000000000000000000000000000056f",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0e0e020000000000000000000000000000056f\"}"],
        true,
    );
}

/// `set_initial_attitude_reply` (tests/vectors/mip/filter_01_1f.yaml:64)
#[test]
fn case_set_initial_attitude_reply() {
    check(
        "75650d0404f10200e2b4",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":2,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `set_initial_attitude_getting_started` (tests/vectors/mip/filter_01_1f.yaml:74)
#[test]
fn case_set_initial_attitude_getting_started() {
    check(
        "75650d0e0e02bae3ed9b3c7d6ddfbf855cf5c409",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":2,\"name\":\"set_initial_attitude\",\"values\":{\"roll\":-0.001738953753374517,\"pitch\":0.01546808984130621,\"heading\":-1.04189932346344}}]}",
        ],
        false,
    );
}

/// `set_initial_attitude_getting_started_table_published` (tests/vectors/mip/filter_01_1f.yaml:87)
#[test]
fn case_set_initial_attitude_getting_started_table_published() {
    check(
        "75650d060602bae3ed9b3c7d6ddfbf855cf5c409",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d060602bae3ed9b3c7d6ddfbf855cf5c409\"}"],
        true,
    );
}

/// `set_initial_heading_command` (tests/vectors/mip/filter_01_1f.yaml:100)
#[test]
fn case_set_initial_heading_command() {
    check(
        "75650d06060300000000f6e4",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":3,\"name\":\"set_initial_heading\",\"values\":{\"heading\":0.0}}]}",
        ],
        false,
    );
}

/// `set_initial_heading_reply` (tests/vectors/mip/filter_01_1f.yaml:110)
#[test]
fn case_set_initial_heading_reply() {
    check(
        "75650d0404f10300e3b6",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":3,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `set_initial_heading_half_pi` (tests/vectors/mip/filter_01_1f.yaml:118)
#[test]
fn case_set_initial_heading_half_pi() {
    check(
        "75650d0606033fc90fdbe834",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":3,\"name\":\"set_initial_heading\",\"values\":{\"heading\":1.5707963705062866}}]}",
        ],
        false,
    );
}

/// `run_filter_command` (tests/vectors/mip/filter_01_1f.yaml:130)
#[test]
fn case_run_filter_command() {
    check(
        "75650d020205f0fa",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":5,\"name\":\"run_filter\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `run_filter_reply` (tests/vectors/mip/filter_01_1f.yaml:139)
#[test]
fn case_run_filter_reply() {
    check(
        "75650d0404f10500e5ba",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":5,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `vehicle_dynamics_mode_write` (tests/vectors/mip/filter_01_1f.yaml:149)
#[test]
fn case_vehicle_dynamics_mode_write() {
    check(
        "75650d04041001010110",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":16,\"name\":\"vehicle_dynamics_mode\",\"values\":{\"function\":1,\"mode\":1}}]}",
        ],
        false,
    );
}

/// `vehicle_dynamics_mode_copy_paste_published` (tests/vectors/mip/filter_01_1f.yaml:159)
#[test]
fn case_vehicle_dynamics_mode_copy_paste_published() {
    check(
        "75650c04041001010110",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c04041001010110\"}"],
        true,
    );
}

/// `vehicle_dynamics_mode_reply` (tests/vectors/mip/filter_01_1f.yaml:170)
#[test]
fn case_vehicle_dynamics_mode_reply() {
    check(
        "75650d0404f11000f0d0",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":16,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `vehicle_dynamics_mode_write_airborne_high_g` (tests/vectors/mip/filter_01_1f.yaml:178)
#[test]
fn case_vehicle_dynamics_mode_write_airborne_high_g() {
    check(
        "75650d04041001040413",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":16,\"name\":\"vehicle_dynamics_mode\",\"values\":{\"function\":1,\"mode\":4}}]}",
        ],
        false,
    );
}

/// `vehicle_dynamics_mode_read` (tests/vectors/mip/filter_01_1f.yaml:187)
#[test]
fn case_vehicle_dynamics_mode_read() {
    check(
        "75650d03031002ff09",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":16,\"name\":\"vehicle_dynamics_mode\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `vehicle_dynamics_mode_read_reply` (tests/vectors/mip/filter_01_1f.yaml:196)
#[test]
fn case_vehicle_dynamics_mode_read_reply() {
    check(
        "75650d0704f1100003800278c3",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":16,\"ack_code\":0}},{\"descriptor\":128,\"name\":\"vehicle_dynamics_mode_response\",\"values\":{\"mode\":2}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_transform_write` (tests/vectors/mip/filter_01_1f.yaml:210)
#[test]
fn case_sensor_to_vehicle_transform_write() {
    check(
        "75650d0f0f11010000000000000000000000001772",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":17,\"name\":\"sensor_to_vehicle_transform\",\"values\":{\"function\":1,\"roll\":0.0,\"pitch\":0.0,\"yaw\":0.0}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_transform_copy_paste_published` (tests/vectors/mip/filter_01_1f.yaml:218)
#[test]
fn case_sensor_to_vehicle_transform_copy_paste_published() {
    check(
        "75650d0f0f1101000000000000000000001772",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0f0f1101000000000000000000001772\"}"],
        true,
    );
}

/// `sensor_to_vehicle_transform_reply` (tests/vectors/mip/filter_01_1f.yaml:230)
#[test]
fn case_sensor_to_vehicle_transform_reply() {
    check(
        "75650d0404f11100f1d2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_transform_write_rotated` (tests/vectors/mip/filter_01_1f.yaml:238)
#[test]
fn case_sensor_to_vehicle_transform_write_rotated() {
    check(
        "75650d0f0f110140490fdb00000000bfc90fdbfc2e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":17,\"name\":\"sensor_to_vehicle_transform\",\"values\":{\"function\":1,\"roll\":3.1415927410125732,\"pitch\":0.0,\"yaw\":-1.5707963705062866}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_transform_read` (tests/vectors/mip/filter_01_1f.yaml:249)
#[test]
fn case_sensor_to_vehicle_transform_read() {
    check(
        "75650d03031102000b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":17,\"name\":\"sensor_to_vehicle_transform\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_transform_read_reply` (tests/vectors/mip/filter_01_1f.yaml:258)
#[test]
fn case_sensor_to_vehicle_transform_read_reply() {
    check(
        "75650d1204f111000e8100000000000000003fc90fdb80ab",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"sensor_to_vehicle_transform_response\",\"values\":{\"roll\":0.0,\"pitch\":0.0,\"yaw\":1.5707963705062866}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_offset_write` (tests/vectors/mip/filter_01_1f.yaml:271)
#[test]
fn case_sensor_to_vehicle_offset_write() {
    check(
        "75650d0f0f12010000000000000000000000001880",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":18,\"name\":\"sensor_to_vehicle_offset\",\"values\":{\"function\":1,\"offset\":[0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_offset_reply` (tests/vectors/mip/filter_01_1f.yaml:281)
#[test]
fn case_sensor_to_vehicle_offset_reply() {
    check(
        "75650d0404f11200f2d4",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":18,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `sensor_to_vehicle_offset_read_reply` (tests/vectors/mip/filter_01_1f.yaml:289)
#[test]
fn case_sensor_to_vehicle_offset_read_reply() {
    check(
        "75650d1204f112000e823e800000bf0000003f800000cc54",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":18,\"ack_code\":0}},{\"descriptor\":130,\"name\":\"sensor_to_vehicle_offset_response\",\"values\":{\"offset\":[0.25,-0.5,1.0]}}]}",
        ],
        false,
    );
}

/// `antenna_offset_write` (tests/vectors/mip/filter_01_1f.yaml:302)
#[test]
fn case_antenna_offset_write() {
    check(
        "75650d0f0f1301000000000000000000000000198e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":19,\"name\":\"antenna_offset\",\"values\":{\"function\":1,\"offset\":[0.0,0.0,0.0]}}]}",
        ],
        false,
    );
}

/// `antenna_offset_reply` (tests/vectors/mip/filter_01_1f.yaml:312)
#[test]
fn case_antenna_offset_reply() {
    check(
        "75650d0404f11300f3d6",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":19,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `antenna_offset_write_cv7_example` (tests/vectors/mip/filter_01_1f.yaml:320)
#[test]
fn case_antenna_offset_write_cv7_example() {
    check(
        "75650d0f0f1301bea3d70a3de147aebf23d70a3173",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":19,\"name\":\"antenna_offset\",\"values\":{\"function\":1,\"offset\":[-0.3199999928474426,0.10999999940395355,-0.6399999856948853]}}]}",
        ],
        false,
    );
}

/// `antenna_offset_read_reply` (tests/vectors/mip/filter_01_1f.yaml:331)
#[test]
fn case_antenna_offset_read_reply() {
    check(
        "75650d1204f113000e83bea3d70a3de147aebf23d70aaa7a",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":19,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"antenna_offset_response\",\"values\":{\"offset\":[-0.3199999928474426,0.10999999940395355,-0.6399999856948853]}}]}",
        ],
        false,
    );
}

/// `estimation_control_write_all` (tests/vectors/mip/filter_01_1f.yaml:346)
#[test]
fn case_estimation_control_write_all() {
    check(
        "75650d05051401ffff0427",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":20,\"name\":\"estimation_control\",\"values\":{\"function\":1,\"flags\":65535}}]}",
        ],
        false,
    );
}

/// `estimation_control_reply` (tests/vectors/mip/filter_01_1f.yaml:356)
#[test]
fn case_estimation_control_reply() {
    check(
        "75650d0404f11400f4d8",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":20,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `estimation_control_write_gyro_bias` (tests/vectors/mip/filter_01_1f.yaml:364)
#[test]
fn case_estimation_control_write_gyro_bias() {
    check(
        "75650d050514010001072b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":20,\"name\":\"estimation_control\",\"values\":{\"function\":1,\"flags\":1}}]}",
        ],
        false,
    );
}

/// `estimation_control_read_reply` (tests/vectors/mip/filter_01_1f.yaml:373)
#[test]
fn case_estimation_control_read_reply() {
    check(
        "75650d0804f1140004840063e3cb",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":20,\"ack_code\":0}},{\"descriptor\":132,\"name\":\"estimation_control_response\",\"values\":{\"flags\":99}}]}",
        ],
        false,
    );
}

/// `gnss_source_control_write_external` (tests/vectors/mip/filter_01_1f.yaml:388)
#[test]
fn case_gnss_source_control_write_external() {
    check(
        "75650d04041501020720",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":21,\"name\":\"gnss_source_control\",\"values\":{\"function\":1,\"source\":2}}]}",
        ],
        false,
    );
}

/// `gnss_source_control_reply` (tests/vectors/mip/filter_01_1f.yaml:398)
#[test]
fn case_gnss_source_control_reply() {
    check(
        "75650d0404f11500f5da",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":21,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gnss_source_control_write_internal_2` (tests/vectors/mip/filter_01_1f.yaml:406)
#[test]
fn case_gnss_source_control_write_internal_2() {
    check(
        "75650d04041501040922",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":21,\"name\":\"gnss_source_control\",\"values\":{\"function\":1,\"source\":4}}]}",
        ],
        false,
    );
}

/// `gnss_source_control_save` (tests/vectors/mip/filter_01_1f.yaml:415)
#[test]
fn case_gnss_source_control_save() {
    check(
        "75650d030315030514",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":21,\"name\":\"gnss_source_control\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `gnss_source_control_read_reply_internal_1` (tests/vectors/mip/filter_01_1f.yaml:424)
#[test]
fn case_gnss_source_control_read_reply_internal_1() {
    check(
        "75650d0704f1150003860384e9",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":21,\"ack_code\":0}},{\"descriptor\":134,\"name\":\"gnss_source_control_response\",\"values\":{\"source\":3}}]}",
        ],
        false,
    );
}

/// `gnss_source_control_read_reply_internal` (tests/vectors/mip/filter_01_1f.yaml:435)
#[test]
fn case_gnss_source_control_read_reply_internal() {
    check(
        "75650d0704f1150003860182e7",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":21,\"ack_code\":0}},{\"descriptor\":134,\"name\":\"gnss_source_control_response\",\"values\":{\"source\":1}}]}",
        ],
        false,
    );
}

/// `external_gnss_update_example` (tests/vectors/mip/filter_01_1f.yaml:448)
#[test]
fn case_external_gnss_update_example() {
    check(
        "75650d484816000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000003f0000003f0000003f0000003dcccccd3dcccccd3dcccccd308a",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":22,\"name\":\"external_gnss_update\",\"values\":{\"gps_tow\":0.0,\"gps_week\":0,\"latitude\":0.0,\"longitude\":0.0,\"height\":0.0,\"velocity\":[0.0,0.0,0.0],\"position_uncertainty\":[0.5,0.5,0.5],\"velocity_uncertainty\":[0.10000000149011612,0.10000000149011612,0.10000000149011612]}}]}",
        ],
        false,
    );
}

/// `external_gnss_update_reply` (tests/vectors/mip/filter_01_1f.yaml:478)
#[test]
fn case_external_gnss_update_reply() {
    check(
        "75650d0404f11600f6dc",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":22,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `external_gnss_update_values` (tests/vectors/mip/filter_01_1f.yaml:486)
#[test]
fn case_external_gnss_update_values() {
    check(
        "75650d484816411518010000000008fc4046380000000000c0524c0000000000405e2000000000003fc00000c01000003e0000003f0000003f0000003f8000003dcccccd3dcccccd3e4ccccd8b7a",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":22,\"name\":\"external_gnss_update\",\"values\":{\"gps_tow\":345600.25,\"gps_week\":2300,\"latitude\":44.4375,\"longitude\":-73.1875,\"height\":120.5,\"velocity\":[1.5,-2.25,0.125],\"position_uncertainty\":[0.5,0.5,1.0],\"velocity_uncertainty\":[0.10000000149011612,0.10000000149011612,0.20000000298023224]}}]}",
        ],
        false,
    );
}

/// `external_heading_update_example` (tests/vectors/mip/filter_01_1f.yaml:518)
#[test]
fn case_external_heading_update_example() {
    check(
        "75650d0b0b173dcccccd3dcccccd015934",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":23,\"name\":\"external_heading_update\",\"values\":{\"heading\":0.10000000149011612,\"heading_uncertainty\":0.10000000149011612,\"type\":1}}]}",
        ],
        false,
    );
}

/// `external_heading_update_reply` (tests/vectors/mip/filter_01_1f.yaml:529)
#[test]
fn case_external_heading_update_reply() {
    check(
        "75650d0404f11700f7de",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":23,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `external_heading_update_magnetic` (tests/vectors/mip/filter_01_1f.yaml:537)
#[test]
fn case_external_heading_update_magnetic() {
    check(
        "75650d0b0b17c02000003d4ccccd02180e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":23,\"name\":\"external_heading_update\",\"values\":{\"heading\":-2.5,\"heading_uncertainty\":0.05000000074505806,\"type\":2}}]}",
        ],
        false,
    );
}

/// `heading_update_control_write_magnetometer` (tests/vectors/mip/filter_01_1f.yaml:549)
#[test]
fn case_heading_update_control_write_magnetometer() {
    check(
        "75650d04041801010928",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":24,\"name\":\"heading_update_control\",\"values\":{\"function\":1,\"source\":1}}]}",
        ],
        false,
    );
}

/// `heading_update_control_reply` (tests/vectors/mip/filter_01_1f.yaml:559)
#[test]
fn case_heading_update_control_reply() {
    check(
        "75650d0404f11800f8e0",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":24,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `heading_update_control_read` (tests/vectors/mip/filter_01_1f.yaml:567)
#[test]
fn case_heading_update_control_read() {
    check(
        "75650d030318020719",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":24,\"name\":\"heading_update_control\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `heading_update_control_read_reply` (tests/vectors/mip/filter_01_1f.yaml:576)
#[test]
fn case_heading_update_control_read_reply() {
    check(
        "75650d0704f118000387078cfe",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":24,\"ack_code\":0}},{\"descriptor\":135,\"name\":\"heading_update_control_response\",\"values\":{\"source\":7}}]}",
        ],
        false,
    );
}

/// `auto_init_control_write_enable` (tests/vectors/mip/filter_01_1f.yaml:589)
#[test]
fn case_auto_init_control_write_enable() {
    check(
        "75650d04041901010a2b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":25,\"name\":\"auto_init_control\",\"values\":{\"function\":1,\"enable\":1}}]}",
        ],
        false,
    );
}

/// `auto_init_control_reply` (tests/vectors/mip/filter_01_1f.yaml:599)
#[test]
fn case_auto_init_control_reply() {
    check(
        "75650d0404f11900f9e2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":25,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `auto_init_control_read` (tests/vectors/mip/filter_01_1f.yaml:607)
#[test]
fn case_auto_init_control_read() {
    check(
        "75650d03031902081b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":25,\"name\":\"auto_init_control\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `auto_init_control_read_reply` (tests/vectors/mip/filter_01_1f.yaml:616)
#[test]
fn case_auto_init_control_read_reply() {
    check(
        "75650d0704f1190003880087fe",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":25,\"ack_code\":0}},{\"descriptor\":136,\"name\":\"auto_init_control_response\",\"values\":{\"enable\":0}}]}",
        ],
        false,
    );
}

/// `accel_noise_write` (tests/vectors/mip/filter_01_1f.yaml:627)
#[test]
fn case_accel_noise_write() {
    check(
        "75650d0f0f1a013ca3d70a3ca3d70a3ca3d70a60a3",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":26,\"name\":\"accel_noise\",\"values\":{\"function\":1,\"noise\":[0.019999999552965164,0.019999999552965164,0.019999999552965164]}}]}",
        ],
        false,
    );
}

/// `accel_noise_copy_paste_published` (tests/vectors/mip/filter_01_1f.yaml:635)
#[test]
fn case_accel_noise_copy_paste_published() {
    check(
        "75650d0f0f011a013ca3d70a3ca3d70a3ca3d760a3",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0f0f011a013ca3d70a3ca3d70a3ca3d760a3\"}"],
        true,
    );
}

/// `accel_noise_reply` (tests/vectors/mip/filter_01_1f.yaml:648)
#[test]
fn case_accel_noise_reply() {
    check(
        "75650d0404f11a00fae4",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":26,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `accel_noise_read_reply` (tests/vectors/mip/filter_01_1f.yaml:656)
#[test]
fn case_accel_noise_read_reply() {
    check(
        "75650d1204f11a000e893ca3d70a3ca3d70a3ca3d70adf06",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":26,\"ack_code\":0}},{\"descriptor\":137,\"name\":\"accel_noise_response\",\"values\":{\"noise\":[0.019999999552965164,0.019999999552965164,0.019999999552965164]}}]}",
        ],
        false,
    );
}

/// `gyro_noise_write` (tests/vectors/mip/filter_01_1f.yaml:671)
#[test]
fn case_gyro_noise_write() {
    check(
        "75650d0f0f1b013a0d4bad3a0d4bad3a0d4baddee8",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":27,\"name\":\"gyro_noise\",\"values\":{\"function\":1,\"noise\":[0.0005389999714680016,0.0005389999714680016,0.0005389999714680016]}}]}",
        ],
        false,
    );
}

/// `gyro_noise_reply` (tests/vectors/mip/filter_01_1f.yaml:686)
#[test]
fn case_gyro_noise_reply() {
    check(
        "75650d0404f11b00fbe6",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":27,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gyro_noise_default` (tests/vectors/mip/filter_01_1f.yaml:694)
#[test]
fn case_gyro_noise_default() {
    check(
        "75650d03031b050d22",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":27,\"name\":\"gyro_noise\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `gyro_noise_read_reply` (tests/vectors/mip/filter_01_1f.yaml:703)
#[test]
fn case_gyro_noise_read_reply() {
    check(
        "75650d1204f11b000e8a386212af386212af386212afb23f",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":27,\"ack_code\":0}},{\"descriptor\":138,\"name\":\"gyro_noise_response\",\"values\":{\"noise\":[5.3899999329587445e-05,5.3899999329587445e-05,5.3899999329587445e-05]}}]}",
        ],
        false,
    );
}

/// `accel_bias_model_example` (tests/vectors/mip/filter_01_1f.yaml:718)
#[test]
fn case_accel_bias_model_example() {
    check(
        "75650d1b1b1c013c23d70a3c23d70a3c23d70a3a1d49523a1d49523a1d4952d02c",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":28,\"name\":\"accel_bias_model\",\"values\":{\"function\":1,\"beta\":[0.009999999776482582,0.009999999776482582,0.009999999776482582],\"noise\":[0.0006000000284984708,0.0006000000284984708,0.0006000000284984708]}}]}",
        ],
        false,
    );
}

/// `accel_bias_model_reply` (tests/vectors/mip/filter_01_1f.yaml:733)
#[test]
fn case_accel_bias_model_reply() {
    check(
        "75650d0404f11c00fce8",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":28,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `accel_bias_model_read` (tests/vectors/mip/filter_01_1f.yaml:741)
#[test]
fn case_accel_bias_model_read() {
    check(
        "75650d03031c020b21",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":28,\"name\":\"accel_bias_model\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `accel_bias_model_read_reply` (tests/vectors/mip/filter_01_1f.yaml:750)
#[test]
fn case_accel_bias_model_read_reply() {
    check(
        "75650d1e04f11c001a8b3c23d70a3c23d70a3c23d70a3a1d49523a1d49523a1d495251d1",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":28,\"ack_code\":0}},{\"descriptor\":139,\"name\":\"accel_bias_model_response\",\"values\":{\"beta\":[0.009999999776482582,0.009999999776482582,0.009999999776482582],\"noise\":[0.0006000000284984708,0.0006000000284984708,0.0006000000284984708]}}]}",
        ],
        false,
    );
}

/// `gyro_bias_model_example` (tests/vectors/mip/filter_01_1f.yaml:768)
#[test]
fn case_gyro_bias_model_example() {
    check(
        "75650d1b1b1d013c23d70a3c23d70a3c23d70a3927c5ac3927c5ac3927c5ac6efe",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":29,\"name\":\"gyro_bias_model\",\"values\":{\"function\":1,\"beta\":[0.009999999776482582,0.009999999776482582,0.009999999776482582],\"noise\":[0.00015999999595806003,0.00015999999595806003,0.00015999999595806003]}}]}",
        ],
        false,
    );
}

/// `gyro_bias_model_reply` (tests/vectors/mip/filter_01_1f.yaml:782)
#[test]
fn case_gyro_bias_model_reply() {
    check(
        "75650d0404f11d00fdea",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":29,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gyro_bias_model_load` (tests/vectors/mip/filter_01_1f.yaml:790)
#[test]
fn case_gyro_bias_model_load() {
    check(
        "75650d03031d040e25",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":29,\"name\":\"gyro_bias_model\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `gyro_bias_model_read_reply` (tests/vectors/mip/filter_01_1f.yaml:799)
#[test]
fn case_gyro_bias_model_read_reply() {
    check(
        "75650d1e04f11d001a8c3c23d70a3c23d70a3c23d70a3927c5ac3927c5ac3927c5acf0be",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":29,\"ack_code\":0}},{\"descriptor\":140,\"name\":\"gyro_bias_model_response\",\"values\":{\"beta\":[0.009999999776482582,0.009999999776482582,0.009999999776482582],\"noise\":[0.00015999999595806003,0.00015999999595806003,0.00015999999595806003]}}]}",
        ],
        false,
    );
}

/// `zupt_control_write` (tests/vectors/mip/filter_01_1f.yaml:817)
#[test]
fn case_zupt_control_write() {
    check(
        "75650d08081e01010000000017ba",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":30,\"name\":\"zupt_control\",\"values\":{\"function\":1,\"enable\":1,\"threshold\":0.0}}]}",
        ],
        false,
    );
}

/// `zupt_control_write_threshold` (tests/vectors/mip/filter_01_1f.yaml:833)
#[test]
fn case_zupt_control_write_threshold() {
    check(
        "75650d08081e01013c23d70a57cb",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":30,\"name\":\"zupt_control\",\"values\":{\"function\":1,\"enable\":1,\"threshold\":0.009999999776482582}}]}",
        ],
        false,
    );
}

/// `zupt_control_reply` (tests/vectors/mip/filter_01_1f.yaml:844)
#[test]
fn case_zupt_control_reply() {
    check(
        "75650d0404f11e00feec",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":30,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `zupt_control_read_reply` (tests/vectors/mip/filter_01_1f.yaml:852)
#[test]
fn case_zupt_control_read_reply() {
    check(
        "75650d0b04f11e00078d013dcccccd3c73",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":30,\"ack_code\":0}},{\"descriptor\":141,\"name\":\"zupt_control_response\",\"values\":{\"enable\":1,\"threshold\":0.10000000149011612}}]}",
        ],
        false,
    );
}

/// `external_heading_update_with_time_example` (tests/vectors/mip/filter_01_1f.yaml:865)
#[test]
fn case_external_heading_update_with_time_example() {
    check(
        "75650d15151f40dd4c000000000006a43c23d70a3c23d70a01c4a6",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":31,\"name\":\"external_heading_update_with_time\",\"values\":{\"gps_tow\":30000.0,\"gps_week\":1700,\"heading\":0.009999999776482582,\"heading_uncertainty\":0.009999999776482582,\"type\":1}}]}",
        ],
        false,
    );
}

/// `external_heading_update_with_time_reply` (tests/vectors/mip/filter_01_1f.yaml:879)
#[test]
fn case_external_heading_update_with_time_reply() {
    check(
        "75650d0404f11f00ffee",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":31,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `external_heading_update_with_time_reply_table_published` (tests/vectors/mip/filter_01_1f.yaml:888)
#[test]
fn case_external_heading_update_with_time_reply_table_published() {
    check(
        "75650d0404f10100ffee",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f10100ffee\"}"],
        true,
    );
}

/// `external_heading_update_with_time_nack` (tests/vectors/mip/filter_01_1f.yaml:899)
#[test]
fn case_external_heading_update_with_time_nack() {
    check(
        "75650d0404f11f0302f1",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":31,\"ack_code\":3}}]}",
        ],
        false,
    );
}

/// `external_heading_update_with_time_cv7` (tests/vectors/mip/filter_01_1f.yaml:910)
#[test]
fn case_external_heading_update_with_time_cv7() {
    check(
        "75650d15151f411518010000000008fcc02000003d4ccccd02a749",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":31,\"name\":\"external_heading_update_with_time\",\"values\":{\"gps_tow\":345600.25,\"gps_week\":2300,\"heading\":-2.5,\"heading_uncertainty\":0.05000000074505806,\"type\":2}}]}",
        ],
        false,
    );
}

/// `pitch_roll_aiding_control_write` (tests/vectors/mip/filter_20_64.yaml:14)
#[test]
fn case_pitch_roll_aiding_control_write() {
    check(
        "75650d04044b01013cc1",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":75,\"name\":\"pitch_roll_aiding_control\",\"values\":{\"function\":1,\"source\":1}}]}",
        ],
        false,
    );
}

/// `pitch_roll_aiding_control_ack_published` (tests/vectors/mip/filter_20_64.yaml:24)
#[test]
fn case_pitch_roll_aiding_control_ack_published() {
    check(
        "75650d0404f14700b9f0",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f14700b9f0\"}"],
        true,
    );
}

/// `pitch_roll_aiding_control_ack` (tests/vectors/mip/filter_20_64.yaml:38)
#[test]
fn case_pitch_roll_aiding_control_ack() {
    check(
        "75650d0404f14b002b46",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":75,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `pitch_roll_aiding_control_read` (tests/vectors/mip/filter_20_64.yaml:52)
#[test]
fn case_pitch_roll_aiding_control_read() {
    check(
        "75650d03034b023a7f",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":75,\"name\":\"pitch_roll_aiding_control\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `pitch_roll_aiding_control_read_reply` (tests/vectors/mip/filter_20_64.yaml:65)
#[test]
fn case_pitch_roll_aiding_control_read_reply() {
    check(
        "75650d0704f14b0003bb00ec5e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":75,\"ack_code\":0}},{\"descriptor\":187,\"name\":\"pitch_roll_aiding_control_response\",\"values\":{\"source\":0}}]}",
        ],
        false,
    );
}

/// `altitude_aiding_control_write` (tests/vectors/mip/filter_20_64.yaml:81)
#[test]
fn case_altitude_aiding_control_write() {
    check(
        "75650d040447010138b5",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":71,\"name\":\"altitude_aiding_control\",\"values\":{\"function\":1,\"source\":1}}]}",
        ],
        false,
    );
}

/// `altitude_aiding_control_ack` (tests/vectors/mip/filter_20_64.yaml:91)
#[test]
fn case_altitude_aiding_control_ack() {
    check(
        "75650d0404f14700273e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":71,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `altitude_aiding_control_read_reply` (tests/vectors/mip/filter_20_64.yaml:100)
#[test]
fn case_altitude_aiding_control_read_reply() {
    check(
        "75650d0704f1470003b701e543",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":71,\"ack_code\":0}},{\"descriptor\":183,\"name\":\"altitude_aiding_control_response\",\"values\":{\"source\":1}}]}",
        ],
        false,
    );
}

/// `mag_noise_std_dev_write` (tests/vectors/mip/filter_20_64.yaml:116)
#[test]
fn case_mag_noise_std_dev_write() {
    check(
        "75650d0f0f42013ca3d70a3ca3d70a3ca3d70a88d3",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":66,\"name\":\"mag_noise_std_dev\",\"values\":{\"function\":1,\"noise\":[0.019999999552965164,0.019999999552965164,0.019999999552965164]}}]}",
        ],
        false,
    );
}

/// `mag_noise_std_dev_ack` (tests/vectors/mip/filter_20_64.yaml:129)
#[test]
fn case_mag_noise_std_dev_ack() {
    check(
        "75650d0404f142002234",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":66,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `mag_noise_std_dev_read_reply` (tests/vectors/mip/filter_20_64.yaml:138)
#[test]
fn case_mag_noise_std_dev_read_reply() {
    check(
        "75650d1204f142000eb13ca3d70a3d0000003f0000002b50",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":66,\"ack_code\":0}},{\"descriptor\":177,\"name\":\"mag_noise_std_dev_response\",\"values\":{\"noise\":[0.019999999552965164,0.03125,0.5]}}]}",
        ],
        false,
    );
}

/// `gravity_noise_std_dev_write` (tests/vectors/mip/filter_20_64.yaml:154)
#[test]
fn case_gravity_noise_std_dev_write() {
    check(
        "75650d0f0f28013c23d70a3c23d70a3c23d70aeee7",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":40,\"name\":\"gravity_noise_std_dev\",\"values\":{\"function\":1,\"noise\":[0.009999999776482582,0.009999999776482582,0.009999999776482582]}}]}",
        ],
        false,
    );
}

/// `gravity_noise_std_dev_ack` (tests/vectors/mip/filter_20_64.yaml:170)
#[test]
fn case_gravity_noise_std_dev_ack() {
    check(
        "75650d0404f128000800",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gravity_noise_std_dev_read` (tests/vectors/mip/filter_20_64.yaml:183)
#[test]
fn case_gravity_noise_std_dev_read() {
    check(
        "75650d030328021739",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":40,\"name\":\"gravity_noise_std_dev\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `gravity_noise_std_dev_read_reply` (tests/vectors/mip/filter_20_64.yaml:196)
#[test]
fn case_gravity_noise_std_dev_read_reply() {
    check(
        "75650d1204f128000e933c23d70a3c8000003e800000719e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}},{\"descriptor\":147,\"name\":\"gravity_noise_std_dev_response\",\"values\":{\"noise\":[0.009999999776482582,0.015625,0.25]}}]}",
        ],
        false,
    );
}

/// `gravity_noise_std_dev_load` (tests/vectors/mip/filter_20_64.yaml:212)
#[test]
fn case_gravity_noise_std_dev_load() {
    check(
        "75650d03032804193b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":40,\"name\":\"gravity_noise_std_dev\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `pressure_altitude_noise_std_dev_write` (tests/vectors/mip/filter_20_64.yaml:225)
#[test]
fn case_pressure_altitude_noise_std_dev_write() {
    check(
        "75650d070729013f800000de4e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":41,\"name\":\"pressure_altitude_noise_std_dev\",\"values\":{\"function\":1,\"noise\":1.0}}]}",
        ],
        false,
    );
}

/// `pressure_altitude_noise_std_dev_write_published` (tests/vectors/mip/filter_20_64.yaml:239)
#[test]
fn case_pressure_altitude_noise_std_dev_write_published() {
    check(
        "75650d050529013f800000de4e",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d050529013f800000de4e\"}"],
        true,
    );
}

/// `pressure_altitude_noise_std_dev_ack` (tests/vectors/mip/filter_20_64.yaml:252)
#[test]
fn case_pressure_altitude_noise_std_dev_ack() {
    check(
        "75650d0404f129000902",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":41,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `pressure_altitude_noise_std_dev_ack_published` (tests/vectors/mip/filter_20_64.yaml:266)
#[test]
fn case_pressure_altitude_noise_std_dev_ack_published() {
    check(
        "75650d0404f1290097ac",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f1290097ac\"}"],
        true,
    );
}

/// `pressure_altitude_noise_std_dev_read_reply` (tests/vectors/mip/filter_20_64.yaml:278)
#[test]
fn case_pressure_altitude_noise_std_dev_read_reply() {
    check(
        "75650d0a04f1290006944020000009e2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":41,\"ack_code\":0}},{\"descriptor\":148,\"name\":\"pressure_altitude_noise_std_dev_response\",\"values\":{\"noise\":2.5}}]}",
        ],
        false,
    );
}

/// `hard_iron_offset_noise_write` (tests/vectors/mip/filter_20_64.yaml:294)
#[test]
fn case_hard_iron_offset_noise_write() {
    check(
        "75650d0f0f2b013a83126f3a83126f3a83126febd2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":43,\"name\":\"hard_iron_offset_noise\",\"values\":{\"function\":1,\"noise\":[0.0010000000474974513,0.0010000000474974513,0.0010000000474974513]}}]}",
        ],
        false,
    );
}

/// `hard_iron_offset_noise_ack` (tests/vectors/mip/filter_20_64.yaml:304)
#[test]
fn case_hard_iron_offset_noise_ack() {
    check(
        "75650d0404f12b000b06",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":43,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `hard_iron_offset_noise_read_reply` (tests/vectors/mip/filter_20_64.yaml:313)
#[test]
fn case_hard_iron_offset_noise_read_reply() {
    check(
        "75650d1204f12b000e963a83126f3b03126f3b83126ff98c",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":43,\"ack_code\":0}},{\"descriptor\":150,\"name\":\"hard_iron_offset_noise_response\",\"values\":{\"noise\":[0.0010000000474974513,0.0020000000949949026,0.004000000189989805]}}]}",
        ],
        false,
    );
}

/// `soft_iron_matrix_noise_write` (tests/vectors/mip/filter_20_64.yaml:329)
#[test]
fn case_soft_iron_matrix_noise_write() {
    check(
        "75650d27272c0138d1b71738d1b71738d1b71738d1b71738d1b71738d1b71738d1b71738d1b71738d1b717f18c",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":44,\"name\":\"soft_iron_matrix_noise\",\"values\":{\"function\":1,\"noise\":[9.999999747378752e-05,9.999999747378752e-05,9.999999747378752e-05,9.999999747378752e-05,9.999999747378752e-05,9.999999747378752e-05,9.999999747378752e-05,9.999999747378752e-05,9.999999747378752e-05]}}]}",
        ],
        false,
    );
}

/// `soft_iron_matrix_noise_table_published` (tests/vectors/mip/filter_20_64.yaml:343)
#[test]
fn case_soft_iron_matrix_noise_table_published() {
    check(
        "75650d0f0f2c0138d1b71738d1b71738d1b717f18c",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0f0f2c0138d1b71738d1b71738d1b717f18c\"}"],
        true,
    );
}

/// `soft_iron_matrix_noise_ack` (tests/vectors/mip/filter_20_64.yaml:357)
#[test]
fn case_soft_iron_matrix_noise_ack() {
    check(
        "75650d0404f12c000c08",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":44,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `soft_iron_matrix_noise_ack_published` (tests/vectors/mip/filter_20_64.yaml:371)
#[test]
fn case_soft_iron_matrix_noise_ack_published() {
    check(
        "75650d0404f12c009ab2",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f12c009ab2\"}"],
        true,
    );
}

/// `soft_iron_matrix_noise_read_reply` (tests/vectors/mip/filter_20_64.yaml:383)
#[test]
fn case_soft_iron_matrix_noise_read_reply() {
    check(
        "75650d2a04f12c00269738d1b7170000000000000000000000003951b717000000000000000000000000399d49528fdc",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":44,\"ack_code\":0}},{\"descriptor\":151,\"name\":\"soft_iron_matrix_noise_response\",\"values\":{\"noise\":[9.999999747378752e-05,0.0,0.0,0.0,0.00019999999494757503,0.0,0.0,0.0,0.0003000000142492354]}}]}",
        ],
        false,
    );
}

/// `zero_angular_rate_update_control_write` (tests/vectors/mip/filter_20_64.yaml:401)
#[test]
fn case_zero_angular_rate_update_control_write() {
    check(
        "75650d08082001010000000019c8",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":32,\"name\":\"zero_angular_rate_update_control\",\"values\":{\"function\":1,\"enable\":1,\"threshold\":0.0}}]}",
        ],
        false,
    );
}

/// `zero_angular_rate_update_control_ack` (tests/vectors/mip/filter_20_64.yaml:411)
#[test]
fn case_zero_angular_rate_update_control_ack() {
    check(
        "75650d0404f1200000f0",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":32,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `zero_angular_rate_update_control_read_reply` (tests/vectors/mip/filter_20_64.yaml:420)
#[test]
fn case_zero_angular_rate_update_control_read_reply() {
    check(
        "75650d0b04f12000078e013d4ccccdbf0b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":32,\"ack_code\":0}},{\"descriptor\":142,\"name\":\"zero_angular_rate_update_control_response\",\"values\":{\"enable\":1,\"threshold\":0.05000000074505806}}]}",
        ],
        false,
    );
}

/// `zero_angular_rate_update_control_default` (tests/vectors/mip/filter_20_64.yaml:436)
#[test]
fn case_zero_angular_rate_update_control_default() {
    check(
        "75650d03032005122c",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":32,\"name\":\"zero_angular_rate_update_control\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `tare_orientation_write` (tests/vectors/mip/filter_20_64.yaml:450)
#[test]
fn case_tare_orientation_write() {
    check(
        "75650d04042101071849",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":33,\"name\":\"tare_orientation\",\"values\":{\"function\":1,\"axes\":7}}]}",
        ],
        false,
    );
}

/// `tare_orientation_ack` (tests/vectors/mip/filter_20_64.yaml:460)
#[test]
fn case_tare_orientation_ack() {
    check(
        "75650d0404f1210001f2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":33,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `tare_orientation_reset_all` (tests/vectors/mip/filter_20_64.yaml:473)
#[test]
fn case_tare_orientation_reset_all() {
    check(
        "75650d04042101001142",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":33,\"name\":\"tare_orientation\",\"values\":{\"function\":1,\"axes\":0}}]}",
        ],
        false,
    );
}

/// `tare_orientation_save` (tests/vectors/mip/filter_20_64.yaml:486)
#[test]
fn case_tare_orientation_save() {
    check(
        "75650d03032103112c",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":33,\"name\":\"tare_orientation\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `commanded_zupt` (tests/vectors/mip/filter_20_64.yaml:500)
#[test]
fn case_commanded_zupt() {
    check(
        "75650d0202220d17",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":34,\"name\":\"commanded_zupt\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `commanded_zupt_ack` (tests/vectors/mip/filter_20_64.yaml:510)
#[test]
fn case_commanded_zupt_ack() {
    check(
        "75650d0404f1220002f4",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":34,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `commanded_zero_angular_rate_update` (tests/vectors/mip/filter_20_64.yaml:519)
#[test]
fn case_commanded_zero_angular_rate_update() {
    check(
        "75650d0202230e18",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":35,\"name\":\"commanded_zero_angular_rate_update\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `commanded_zero_angular_rate_update_ack` (tests/vectors/mip/filter_20_64.yaml:529)
#[test]
fn case_commanded_zero_angular_rate_update_ack() {
    check(
        "75650d0404f1230003f6",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":35,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `declination_source_write` (tests/vectors/mip/filter_20_64.yaml:539)
#[test]
fn case_declination_source_write() {
    check(
        "75650d0808430103000000003ec7",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":67,\"name\":\"declination_source\",\"values\":{\"function\":1,\"source\":3,\"declination\":0.0}}]}",
        ],
        false,
    );
}

/// `declination_source_ack` (tests/vectors/mip/filter_20_64.yaml:548)
#[test]
fn case_declination_source_ack() {
    check(
        "75650d0404f143002336",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":67,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `declination_source_read_reply` (tests/vectors/mip/filter_20_64.yaml:557)
#[test]
fn case_declination_source_read_reply() {
    check(
        "75650d0b04f1430007b202be800000235e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":67,\"ack_code\":0}},{\"descriptor\":178,\"name\":\"declination_source_response\",\"values\":{\"source\":2,\"declination\":-0.25}}]}",
        ],
        false,
    );
}

/// `declination_source_write_none_cv7` (tests/vectors/mip/filter_20_64.yaml:574)
#[test]
fn case_declination_source_write_none_cv7() {
    check(
        "75650d0808430101000000003cbd",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":67,\"name\":\"declination_source\",\"values\":{\"function\":1,\"source\":1,\"declination\":0.0}}]}",
        ],
        false,
    );
}

/// `inclination_source_write` (tests/vectors/mip/filter_20_64.yaml:588)
#[test]
fn case_inclination_source_write() {
    check(
        "75650d08084c0103000000004706",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":76,\"name\":\"inclination_source\",\"values\":{\"function\":1,\"source\":3,\"inclination\":0.0}}]}",
        ],
        false,
    );
}

/// `inclination_source_ack` (tests/vectors/mip/filter_20_64.yaml:597)
#[test]
fn case_inclination_source_ack() {
    check(
        "75650d0404f14c002c48",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":76,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `inclination_source_read_reply` (tests/vectors/mip/filter_20_64.yaml:606)
#[test]
fn case_inclination_source_read_reply() {
    check(
        "75650d0b04f14c0007bc033f900000c824",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":76,\"ack_code\":0}},{\"descriptor\":188,\"name\":\"inclination_source_response\",\"values\":{\"source\":3,\"inclination\":1.125}}]}",
        ],
        false,
    );
}

/// `magnetic_field_magnitude_source_write` (tests/vectors/mip/filter_20_64.yaml:622)
#[test]
fn case_magnetic_field_magnitude_source_write() {
    check(
        "75650d08084d01033f0000008709",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":77,\"name\":\"magnetic_field_magnitude_source\",\"values\":{\"function\":1,\"source\":3,\"magnitude\":0.5}}]}",
        ],
        false,
    );
}

/// `magnetic_field_magnitude_source_ack` (tests/vectors/mip/filter_20_64.yaml:638)
#[test]
fn case_magnetic_field_magnitude_source_ack() {
    check(
        "75650d0404f14d002d4a",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":77,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `magnetic_field_magnitude_source_read_reply` (tests/vectors/mip/filter_20_64.yaml:647)
#[test]
fn case_magnetic_field_magnitude_source_read_reply() {
    check(
        "75650d0b04f14d0007bd013f0000003879",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":77,\"ack_code\":0}},{\"descriptor\":189,\"name\":\"magnetic_field_magnitude_source_response\",\"values\":{\"source\":1,\"magnitude\":0.5}}]}",
        ],
        false,
    );
}

/// `gravity_magnitude_adaptive_measurement_write` (tests/vectors/mip/filter_20_64.yaml:664)
#[test]
fn case_gravity_magnitude_adaptive_measurement_write() {
    check(
        "75650d1c1c4401013f800000be4ccccd3e4ccccd3e4ccccd3e4ccccd3b83126f6fe8",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":68,\"name\":\"gravity_magnitude_adaptive_measurement\",\"values\":{\"function\":1,\"mode\":1,\"frequency\":1.0,\"low_limit\":-0.20000000298023224,\"high_limit\":0.20000000298023224,\"low_limit_uncertainty\":0.20000000298023224,\"high_limit_uncertainty\":0.20000000298023224,\"minimum_uncertainty\":0.004000000189989805}}]}",
        ],
        false,
    );
}

/// `gravity_magnitude_adaptive_measurement_ack` (tests/vectors/mip/filter_20_64.yaml:680)
#[test]
fn case_gravity_magnitude_adaptive_measurement_ack() {
    check(
        "75650d0404f144002438",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":68,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `gravity_magnitude_adaptive_measurement_ack_published` (tests/vectors/mip/filter_20_64.yaml:694)
#[test]
fn case_gravity_magnitude_adaptive_measurement_ack_published() {
    check(
        "75650d0404f14400b2e2",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f14400b2e2\"}"],
        true,
    );
}

/// `gravity_magnitude_adaptive_measurement_auto_only` (tests/vectors/mip/filter_20_64.yaml:706)
#[test]
fn case_gravity_magnitude_adaptive_measurement_auto_only() {
    check(
        "75650d040444010236ad",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":68,\"name\":\"gravity_magnitude_adaptive_measurement\",\"values\":{\"function\":1,\"mode\":2}}]}",
        ],
        false,
    );
}

/// `gravity_magnitude_adaptive_measurement_read_reply` (tests/vectors/mip/filter_20_64.yaml:720)
#[test]
fn case_gravity_magnitude_adaptive_measurement_read_reply() {
    check(
        "75650d1f04f144001bb3023f800000be4ccccd3e4ccccd3e4ccccd3e4ccccd3b83126f1989",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":68,\"ack_code\":0}},{\"descriptor\":179,\"name\":\"gravity_magnitude_adaptive_measurement_response\",\"values\":{\"mode\":2,\"frequency\":1.0,\"low_limit\":-0.20000000298023224,\"high_limit\":0.20000000298023224,\"low_limit_uncertainty\":0.20000000298023224,\"high_limit_uncertainty\":0.20000000298023224,\"minimum_uncertainty\":0.004000000189989805}}]}",
        ],
        false,
    );
}

/// `mag_magnitude_adaptive_measurement_write` (tests/vectors/mip/filter_20_64.yaml:738)
#[test]
fn case_mag_magnitude_adaptive_measurement_write() {
    check(
        "75650d1c1c4501013f800000be4ccccd3e4ccccd3e4ccccd3e4ccccd3b83126f7003",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":69,\"name\":\"mag_magnitude_adaptive_measurement\",\"values\":{\"function\":1,\"mode\":1,\"frequency\":1.0,\"low_limit\":-0.20000000298023224,\"high_limit\":0.20000000298023224,\"low_limit_uncertainty\":0.20000000298023224,\"high_limit_uncertainty\":0.20000000298023224,\"minimum_uncertainty\":0.004000000189989805}}]}",
        ],
        false,
    );
}

/// `mag_magnitude_adaptive_measurement_ack` (tests/vectors/mip/filter_20_64.yaml:754)
#[test]
fn case_mag_magnitude_adaptive_measurement_ack() {
    check(
        "75650d0404f14500253a",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":69,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `mag_magnitude_adaptive_measurement_ack_published` (tests/vectors/mip/filter_20_64.yaml:768)
#[test]
fn case_mag_magnitude_adaptive_measurement_ack_published() {
    check(
        "75650d0404f14500b3e4",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f14500b3e4\"}"],
        true,
    );
}

/// `mag_magnitude_adaptive_measurement_disable` (tests/vectors/mip/filter_20_64.yaml:780)
#[test]
fn case_mag_magnitude_adaptive_measurement_disable() {
    check(
        "75650d040445010035ae",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":69,\"name\":\"mag_magnitude_adaptive_measurement\",\"values\":{\"function\":1,\"mode\":0}}]}",
        ],
        false,
    );
}

/// `mag_magnitude_adaptive_measurement_read_reply` (tests/vectors/mip/filter_20_64.yaml:793)
#[test]
fn case_mag_magnitude_adaptive_measurement_read_reply() {
    check(
        "75650d1f04f145001bb401400000003e8000003f4000003e0000003e0000003c23d70a49ac",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":69,\"ack_code\":0}},{\"descriptor\":180,\"name\":\"mag_magnitude_adaptive_measurement_response\",\"values\":{\"mode\":1,\"frequency\":2.0,\"low_limit\":0.25,\"high_limit\":0.75,\"low_limit_uncertainty\":0.125,\"high_limit_uncertainty\":0.125,\"minimum_uncertainty\":0.009999999776482582}}]}",
        ],
        false,
    );
}

/// `mag_dip_angle_adaptive_measurement_write` (tests/vectors/mip/filter_20_64.yaml:812)
#[test]
fn case_mag_dip_angle_adaptive_measurement_write() {
    check(
        "75650d1414460101412000003e99999a3e4ccccd3c23d70a255f",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":70,\"name\":\"mag_dip_angle_adaptive_measurement\",\"values\":{\"function\":1,\"mode\":1,\"frequency\":10.0,\"high_limit\":0.30000001192092896,\"high_limit_uncertainty\":0.20000000298023224,\"minimum_uncertainty\":0.009999999776482582}}]}",
        ],
        false,
    );
}

/// `mag_dip_angle_adaptive_measurement_ack` (tests/vectors/mip/filter_20_64.yaml:827)
#[test]
fn case_mag_dip_angle_adaptive_measurement_ack() {
    check(
        "75650d0404f14600263c",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":70,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `mag_dip_angle_adaptive_measurement_ack_published` (tests/vectors/mip/filter_20_64.yaml:841)
#[test]
fn case_mag_dip_angle_adaptive_measurement_ack_published() {
    check(
        "75650d0404f14600b4e6",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f14600b4e6\"}"],
        true,
    );
}

/// `mag_dip_angle_adaptive_measurement_read_reply` (tests/vectors/mip/filter_20_64.yaml:853)
#[test]
fn case_mag_dip_angle_adaptive_measurement_read_reply() {
    check(
        "75650d1704f1460013b500412000003e99999a3e4ccccd3c23d70acfa6",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":70,\"ack_code\":0}},{\"descriptor\":181,\"name\":\"mag_dip_angle_adaptive_measurement_response\",\"values\":{\"mode\":0,\"frequency\":10.0,\"high_limit\":0.30000001192092896,\"high_limit_uncertainty\":0.20000000298023224,\"minimum_uncertainty\":0.009999999776482582}}]}",
        ],
        false,
    );
}

/// `mag_capture_auto_calibration_write` (tests/vectors/mip/filter_20_64.yaml:870)
#[test]
fn case_mag_capture_auto_calibration_write() {
    check(
        "75650d030327011536",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":39,\"name\":\"mag_capture_auto_calibration\",\"values\":{\"function\":1}}]}",
        ],
        false,
    );
}

/// `mag_capture_auto_calibration_table_published` (tests/vectors/mip/filter_20_64.yaml:880)
#[test]
fn case_mag_capture_auto_calibration_table_published() {
    check(
        "75650d020227011536",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d020227011536\"}"],
        true,
    );
}

/// `mag_capture_auto_calibration_ack` (tests/vectors/mip/filter_20_64.yaml:894)
#[test]
fn case_mag_capture_auto_calibration_ack() {
    check(
        "75650d0404f1270007fe",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":39,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `mag_capture_auto_calibration_ack_published` (tests/vectors/mip/filter_20_64.yaml:908)
#[test]
fn case_mag_capture_auto_calibration_ack_published() {
    check(
        "75650d0404f1270095a8",
        None,
        &["{\"offset\":0,\"skipped\":\"75650d0404f1270095a8\"}"],
        true,
    );
}

/// `mag_capture_auto_calibration_save` (tests/vectors/mip/filter_20_64.yaml:920)
#[test]
fn case_mag_capture_auto_calibration_save() {
    check(
        "75650d030327031738",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":39,\"name\":\"mag_capture_auto_calibration\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `aiding_measurement_control_write` (tests/vectors/mip/filter_20_64.yaml:934)
#[test]
fn case_aiding_measurement_control_write() {
    check(
        "75650d060650010004004871",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":80,\"name\":\"aiding_measurement_control\",\"values\":{\"function\":1,\"source\":4,\"enable\":false}}]}",
        ],
        false,
    );
}

/// `aiding_measurement_control_read` (tests/vectors/mip/filter_20_64.yaml:947)
#[test]
fn case_aiding_measurement_control_read() {
    check(
        "75650d050550020001441e",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":80,\"name\":\"aiding_measurement_control\",\"values\":{\"function\":2,\"source\":1}}]}",
        ],
        false,
    );
}

/// `aiding_measurement_control_save_all` (tests/vectors/mip/filter_20_64.yaml:960)
#[test]
fn case_aiding_measurement_control_save_all() {
    check(
        "75650d05055003ffff421d",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":80,\"name\":\"aiding_measurement_control\",\"values\":{\"function\":3,\"source\":65535}}]}",
        ],
        false,
    );
}

/// `aiding_measurement_control_read_reply` (tests/vectors/mip/filter_20_64.yaml:973)
#[test]
fn case_aiding_measurement_control_read_reply() {
    check(
        "75650d0904f1500005d00001010cce",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":80,\"ack_code\":0}},{\"descriptor\":208,\"name\":\"aiding_measurement_control_response\",\"values\":{\"source\":1,\"enable\":true}}]}",
        ],
        false,
    );
}

/// `aiding_measurement_control_write_external_heading` (tests/vectors/mip/filter_20_64.yaml:988)
#[test]
fn case_aiding_measurement_control_write_external_heading() {
    check(
        "75650d060650010005014a74",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":80,\"name\":\"aiding_measurement_control\",\"values\":{\"function\":1,\"source\":5,\"enable\":true}}]}",
        ],
        false,
    );
}

/// `initialization_configuration_write_manual_llh` (tests/vectors/mip/filter_20_64.yaml:1002)
#[test]
fn case_initialization_configuration_write_manual_llh() {
    check(
        "75650d2b2b520100030042b4000040200000bfc000004231c000c292400042c900003f800000bf0000000000000002ba90",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":82,\"name\":\"initialization_configuration\",\"values\":{\"function\":1,\"wait_for_run_command\":0,\"initial_cond_src\":3,\"auto_heading_alignment_selector\":0,\"initial_heading\":90.0,\"initial_pitch\":2.5,\"initial_roll\":-1.5,\"initial_position\":[44.4375,-73.125,100.5],\"initial_velocity\":[1.0,-0.5,0.0],\"reference_frame_selector\":2}}]}",
        ],
        false,
    );
}

/// `initialization_configuration_write_auto` (tests/vectors/mip/filter_20_64.yaml:1022)
#[test]
fn case_initialization_configuration_write_auto() {
    check(
        "75650d2b2b5201010006000000000000000000000000000000000000000000000000000000000000000000000000019831",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":82,\"name\":\"initialization_configuration\",\"values\":{\"function\":1,\"wait_for_run_command\":1,\"initial_cond_src\":0,\"auto_heading_alignment_selector\":6,\"initial_heading\":0.0,\"initial_pitch\":0.0,\"initial_roll\":0.0,\"initial_position\":[0.0,0.0,0.0],\"initial_velocity\":[0.0,0.0,0.0],\"reference_frame_selector\":1}}]}",
        ],
        false,
    );
}

/// `initialization_configuration_read` (tests/vectors/mip/filter_20_64.yaml:1040)
#[test]
fn case_initialization_configuration_read() {
    check(
        "75650d03035202418d",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":82,\"name\":\"initialization_configuration\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `initialization_configuration_read_reply` (tests/vectors/mip/filter_20_64.yaml:1052)
#[test]
fn case_initialization_configuration_read_reply() {
    check(
        "75650d2e04f152002ad2000109c234000000000000000000004987e357ca93df524a73218e000000003e800000be00000001d954",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":82,\"ack_code\":0}},{\"descriptor\":210,\"name\":\"initialization_configuration_response\",\"values\":{\"wait_for_run_command\":0,\"initial_cond_src\":1,\"auto_heading_alignment_selector\":9,\"initial_heading\":-45.0,\"initial_pitch\":0.0,\"initial_roll\":0.0,\"initial_position\":[1113194.875,-4845481.0,3983459.5],\"initial_velocity\":[0.0,0.25,-0.125],\"reference_frame_selector\":1}}]}",
        ],
        false,
    );
}

/// `adaptive_filter_control_write` (tests/vectors/mip/filter_20_64.yaml:1075)
#[test]
fn case_adaptive_filter_control_write() {
    check(
        "75650d06065301033a981c8d",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":83,\"name\":\"adaptive_filter_control\",\"values\":{\"function\":1,\"level\":3,\"time_limit\":15000}}]}",
        ],
        false,
    );
}

/// `adaptive_filter_control_read_reply` (tests/vectors/mip/filter_20_64.yaml:1088)
#[test]
fn case_adaptive_filter_control_read_reply() {
    check(
        "75650d0904f1530005d30001f405e2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":83,\"ack_code\":0}},{\"descriptor\":211,\"name\":\"adaptive_filter_control_response\",\"values\":{\"level\":0,\"time_limit\":500}}]}",
        ],
        false,
    );
}

/// `multi_antenna_offset_write` (tests/vectors/mip/filter_20_64.yaml:1104)
#[test]
fn case_multi_antenna_offset_write() {
    check(
        "75650d10105401023f000000be800000bf8000001a91",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":84,\"name\":\"multi_antenna_offset\",\"values\":{\"function\":1,\"receiver_id\":2,\"antenna_offset\":[0.5,-0.25,-1.0]}}]}",
        ],
        false,
    );
}

/// `multi_antenna_offset_read` (tests/vectors/mip/filter_20_64.yaml:1118)
#[test]
fn case_multi_antenna_offset_read() {
    check(
        "75650d040454020146de",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":84,\"name\":\"multi_antenna_offset\",\"values\":{\"function\":2,\"receiver_id\":1}}]}",
        ],
        false,
    );
}

/// `multi_antenna_offset_read_reply` (tests/vectors/mip/filter_20_64.yaml:1131)
#[test]
fn case_multi_antenna_offset_read_reply() {
    check(
        "75650d1304f154000fd401bea3d70a3de147aebf23d70a3ffb",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":84,\"ack_code\":0}},{\"descriptor\":212,\"name\":\"multi_antenna_offset_response\",\"values\":{\"receiver_id\":1,\"antenna_offset\":[-0.3199999928474426,0.10999999940395355,-0.6399999856948853]}}]}",
        ],
        false,
    );
}

/// `relative_position_configuration_write` (tests/vectors/mip/filter_20_64.yaml:1149)
#[test]
fn case_relative_position_configuration_write() {
    check(
        "75650d1d1d550101024046380000000000c052480000000000404ba00000000000bd4f",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":85,\"name\":\"relative_position_configuration\",\"values\":{\"function\":1,\"source\":1,\"reference_frame_selector\":2,\"reference_coordinates\":[44.4375,-73.125,55.25]}}]}",
        ],
        false,
    );
}

/// `relative_position_configuration_read_reply` (tests/vectors/mip/filter_20_64.yaml:1164)
#[test]
fn case_relative_position_configuration_read_reply() {
    check(
        "75650d2004f155001cd500014130fc6ae86e47a0c1527bea41eb851f414e6431e0000000a3eb",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":85,\"ack_code\":0}},{\"descriptor\":213,\"name\":\"relative_position_configuration_response\",\"values\":{\"source\":0,\"reference_frame_selector\":1,\"reference_coordinates\":[1113194.907932736,-4845481.03,3983459.75]}}]}",
        ],
        false,
    );
}

/// `reference_point_lever_arm_write` (tests/vectors/mip/filter_20_64.yaml:1182)
#[test]
fn case_reference_point_lever_arm_write() {
    check(
        "75650d10105601013fc0000000000000bf4000005db2",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":86,\"name\":\"reference_point_lever_arm\",\"values\":{\"function\":1,\"ref_point_sel\":1,\"lever_arm_offset\":[1.5,0.0,-0.75]}}]}",
        ],
        false,
    );
}

/// `reference_point_lever_arm_read_reply` (tests/vectors/mip/filter_20_64.yaml:1196)
#[test]
fn case_reference_point_lever_arm_read_reply() {
    check(
        "75650d1304f156000fd6013fc0000000000000bf4000002944",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":86,\"ack_code\":0}},{\"descriptor\":214,\"name\":\"reference_point_lever_arm_response\",\"values\":{\"ref_point_sel\":1,\"lever_arm_offset\":[1.5,0.0,-0.75]}}]}",
        ],
        false,
    );
}

/// `speed_lever_arm_write` (tests/vectors/mip/filter_20_64.yaml:1212)
#[test]
fn case_speed_lever_arm_write() {
    check(
        "75650d1010610101bf000000bf4000003e800000e68b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":97,\"name\":\"speed_lever_arm\",\"values\":{\"function\":1,\"source\":1,\"lever_arm_offset\":[-0.5,-0.75,0.25]}}]}",
        ],
        false,
    );
}

/// `speed_lever_arm_read` (tests/vectors/mip/filter_20_64.yaml:1226)
#[test]
fn case_speed_lever_arm_read() {
    check(
        "75650d04046102015305",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":97,\"name\":\"speed_lever_arm\",\"values\":{\"function\":2,\"source\":1}}]}",
        ],
        false,
    );
}

/// `speed_lever_arm_read_reply` (tests/vectors/mip/filter_20_64.yaml:1239)
#[test]
fn case_speed_lever_arm_read_reply() {
    check(
        "75650d1304f161000fe101bf000000bf4000003e800000bdcd",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":97,\"ack_code\":0}},{\"descriptor\":225,\"name\":\"speed_lever_arm_response\",\"values\":{\"source\":1,\"lever_arm_offset\":[-0.5,-0.75,0.25]}}]}",
        ],
        false,
    );
}

/// `wheeled_vehicle_constraint_control_write` (tests/vectors/mip/filter_20_64.yaml:1255)
#[test]
fn case_wheeled_vehicle_constraint_control_write() {
    check(
        "75650d04046301015409",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":99,\"name\":\"wheeled_vehicle_constraint_control\",\"values\":{\"function\":1,\"enable\":1}}]}",
        ],
        false,
    );
}

/// `wheeled_vehicle_constraint_control_read_reply` (tests/vectors/mip/filter_20_64.yaml:1267)
#[test]
fn case_wheeled_vehicle_constraint_control_read_reply() {
    check(
        "75650d0704f1630003e3002c26",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":99,\"ack_code\":0}},{\"descriptor\":227,\"name\":\"wheeled_vehicle_constraint_control_response\",\"values\":{\"enable\":0}}]}",
        ],
        false,
    );
}

/// `gnss_antenna_calibration_control_write` (tests/vectors/mip/filter_20_64.yaml:1283)
#[test]
fn case_gnss_antenna_calibration_control_write() {
    check(
        "75650d08086401013f0000009ca0",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":100,\"name\":\"gnss_antenna_calibration_control\",\"values\":{\"function\":1,\"enable\":1,\"max_offset\":0.5}}]}",
        ],
        false,
    );
}

/// `gnss_antenna_calibration_control_read_reply` (tests/vectors/mip/filter_20_64.yaml:1297)
#[test]
fn case_gnss_antenna_calibration_control_read_reply() {
    check(
        "75650d0b04f1640007e4013dcccccdd9f3",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":100,\"ack_code\":0}},{\"descriptor\":228,\"name\":\"gnss_antenna_calibration_control_response\",\"values\":{\"enable\":1,\"max_offset\":0.10000000149011612}}]}",
        ],
        false,
    );
}

/// `two_settings_one_packet` (tests/vectors/mip/filter_20_64.yaml:1314)
#[test]
fn case_two_settings_one_packet() {
    check(
        "75650d06036302035302ad6b",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":99,\"name\":\"wheeled_vehicle_constraint_control\",\"values\":{\"function\":2}},{\"descriptor\":83,\"name\":\"adaptive_filter_control\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `two_settings_one_packet_reply` (tests/vectors/mip/filter_20_64.yaml:1328)
#[test]
fn case_two_settings_one_packet_reply() {
    check(
        "75650d1004f1630003e30104f1530005d3023a982abd",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":99,\"ack_code\":0}},{\"descriptor\":227,\"name\":\"wheeled_vehicle_constraint_control_response\",\"values\":{\"enable\":1}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":83,\"ack_code\":0}},{\"descriptor\":211,\"name\":\"adaptive_filter_control_response\",\"values\":{\"level\":2,\"time_limit\":15000}}]}",
        ],
        false,
    );
}

/// `filter_nav_stream_gx5` (tests/vectors/mip/filter_data_01_12.yaml:20)
#[test]
fn case_filter_nav_stream_gx5() {
    check(
        "756582560e1141151802000000000898000108100003000200831c014046400000000000c052500000000000405e080000000000000110023fc00000be8000003e000000000114033f000000bf0000003f000000bf00000000011085",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":17,\"name\":\"gps_timestamp\",\"values\":{\"tow\":345600.5,\"week_number\":2200,\"valid_flags\":1}},{\"descriptor\":16,\"name\":\"filter_status\",\"device\":\"gx5_45\",\"values\":{\"filter_state\":3,\"dynamics_mode\":2,\"status_flags\":131}},{\"descriptor\":1,\"name\":\"llh_position\",\"values\":{\"latitude\":44.5,\"longitude\":-73.25,\"ellipsoid_height\":120.125,\"valid_flags\":1}},{\"descriptor\":2,\"name\":\"ned_velocity\",\"values\":{\"north\":1.5,\"east\":-0.25,\"down\":0.125,\"valid_flags\":1}},{\"descriptor\":3,\"name\":\"attitude_quaternion\",\"values\":{\"q\":[0.5,-0.5,0.5,-0.5],\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_status_gx5_initializing` (tests/vectors/mip/filter_data_01_12.yaml:59)
#[test]
fn case_filter_status_gx5_initializing() {
    check(
        "756582080810000100033000b04d",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":16,\"name\":\"filter_status\",\"device\":\"gx5_45\",\"values\":{\"filter_state\":1,\"dynamics_mode\":3,\"status_flags\":12288}}]}",
        ],
        false,
    );
}

/// `filter_status_cv7_faq_4_1_1025` (tests/vectors/mip/filter_data_01_12.yaml:80)
#[test]
fn case_filter_status_cv7_faq_4_1_1025() {
    check(
        "75658208081000040001040186ff",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":16,\"name\":\"filter_status\",\"device\":\"cv7_ins\",\"values\":{\"filter_state\":4,\"dynamics_mode\":1,\"status_flags\":1025}}]}",
        ],
        false,
    );
}

/// `filter_status_cv7_converging_warnings` (tests/vectors/mip/filter_data_01_12.yaml:96)
#[test]
fn case_filter_status_cv7_converging_warnings() {
    check(
        "75658208081000020001108a1996",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":16,\"name\":\"filter_status\",\"device\":\"cv7_ins\",\"values\":{\"filter_state\":2,\"dynamics_mode\":1,\"status_flags\":4234}}]}",
        ],
        false,
    );
}

/// `filter_attitude_fields` (tests/vectors/mip/filter_data_01_12.yaml:112)
#[test]
fn case_filter_attitude_fields() {
    check(
        "7565825c2804000000003f80000000000000bf800000000000000000000000000000000000003f800000000110053e800000be0000003fc000000001100a3c0000003c8000003d800000000014123b0000003b8000003c0000003c800000000117b7",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":4,\"name\":\"attitude_dcm\",\"values\":{\"dcm\":[0.0,1.0,0.0,-1.0,0.0,0.0,0.0,0.0,1.0],\"valid_flags\":1}},{\"descriptor\":5,\"name\":\"euler_angles\",\"values\":{\"roll\":0.25,\"pitch\":-0.125,\"yaw\":1.5,\"valid_flags\":1}},{\"descriptor\":10,\"name\":\"euler_angles_uncertainty\",\"values\":{\"roll\":0.0078125,\"pitch\":0.015625,\"yaw\":0.0625,\"valid_flags\":0}},{\"descriptor\":18,\"name\":\"quaternion_attitude_uncertainty\",\"values\":{\"q\":[0.001953125,0.00390625,0.0078125,0.015625],\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_bias_and_uncertainty_fields` (tests/vectors/mip/filter_data_01_12.yaml:139)
#[test]
fn case_filter_bias_and_uncertainty_fields() {
    check(
        "7565826010063a800000bb0000003a000000000110073d000000bd8000003e0000000001100b39800000398000003a0000000001100c3c0000003c0000003c800000000110083fa000003fa0000040200000000110093e0000003e0000003e8000000000f5c1",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":6,\"name\":\"gyro_bias\",\"values\":{\"bias\":[0.0009765625,-0.001953125,0.00048828125],\"valid_flags\":1}},{\"descriptor\":7,\"name\":\"accel_bias\",\"values\":{\"bias\":[0.03125,-0.0625,0.125],\"valid_flags\":1}},{\"descriptor\":11,\"name\":\"gyro_bias_uncertainty\",\"values\":{\"bias_uncertainty\":[0.000244140625,0.000244140625,0.00048828125],\"valid_flags\":1}},{\"descriptor\":12,\"name\":\"accel_bias_uncertainty\",\"values\":{\"bias_uncertainty\":[0.0078125,0.0078125,0.015625],\"valid_flags\":1}},{\"descriptor\":8,\"name\":\"llh_position_uncertainty\",\"values\":{\"north\":1.25,\"east\":1.25,\"down\":2.5,\"valid_flags\":1}},{\"descriptor\":9,\"name\":\"ned_velocity_uncertainty\",\"values\":{\"north\":0.125,\"east\":0.125,\"down\":0.25,\"valid_flags\":0}}]}",
        ],
        false,
    );
}

/// `filter_compensated_inertial_gx5` (tests/vectors/mip/filter_data_01_12.yaml:171)
#[test]
fn case_filter_compensated_inertial_gx5() {
    check(
        "75658228100d3f000000bfa00000000000000001100e3d800000bd0000003f8000000001080f411d000000010e41",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":13,\"name\":\"linear_accel\",\"values\":{\"accel\":[0.5,-1.25,0.0],\"valid_flags\":1}},{\"descriptor\":14,\"name\":\"comp_angular_rate\",\"values\":{\"gyro\":[0.0625,-0.03125,1.0],\"valid_flags\":1}},{\"descriptor\":15,\"name\":\"wgs84_gravity_magnitude\",\"values\":{\"gravity_magnitude\":9.8125,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_gravity_comp_accel_pressure_alt_mag_model` (tests/vectors/mip/filter_data_13_51.yaml:5)
#[test]
fn case_filter_gravity_comp_accel_pressure_alt_mag_model() {
    check(
        "7565824010133f000000be800000411c00000001101c3fc00000c0000000c11c00000001082144800000000018153e800000bd0000003f0000003f800000be0000000001b593",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":19,\"name\":\"gravity_vector\",\"values\":{\"gravity\":[0.5,-0.25,9.75],\"valid_flags\":1}},{\"descriptor\":28,\"name\":\"compensated_accel\",\"values\":{\"accel\":[1.5,-2.0,-9.75],\"valid_flags\":1}},{\"descriptor\":33,\"name\":\"pressure_altitude\",\"values\":{\"pressure_altitude\":1024.0,\"valid_flags\":0}},{\"descriptor\":21,\"name\":\"magnetic_model\",\"values\":{\"intensity_north\":0.25,\"intensity_east\":-0.03125,\"intensity_down\":0.5,\"inclination\":1.0,\"declination\":-0.125,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_scale_factors` (tests/vectors/mip/filter_data_13_51.yaml:57)
#[test]
fn case_filter_scale_factors() {
    check(
        "7565824010163c000000bb8000000000000000011017ba8000003b00000039800000000110183d8000003d8000003e000000000010193d0000003c8000003f0000000001d2e6",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":22,\"name\":\"gyro_scale_factor\",\"values\":{\"scale_factor\":[0.0078125,-0.00390625,0.0],\"valid_flags\":1}},{\"descriptor\":23,\"name\":\"accel_scale_factor\",\"values\":{\"scale_factor\":[-0.0009765625,0.001953125,0.000244140625],\"valid_flags\":1}},{\"descriptor\":24,\"name\":\"gyro_scale_factor_uncertainty\",\"values\":{\"scale_factor_uncertainty\":[0.0625,0.0625,0.125],\"valid_flags\":0}},{\"descriptor\":25,\"name\":\"accel_scale_factor_uncertainty\",\"values\":{\"scale_factor_uncertainty\":[0.03125,0.015625,0.5],\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_heading_update_state_standard_atmosphere` (tests/vectors/mip/filter_data_13_51.yaml:102)
#[test]
fn case_filter_heading_update_state_standard_atmosphere() {
    check(
        "756582260e143fc000003d80000000050001182044800000447fe000410800004460b0003f88000000016a9d",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":20,\"name\":\"heading_update_state\",\"values\":{\"heading\":1.5,\"heading_uncertainty\":0.0625,\"source\":5,\"valid_flags\":1}},{\"descriptor\":32,\"name\":\"standard_atmosphere\",\"values\":{\"geometric_altitude\":1024.0,\"geopotential_altitude\":1023.5,\"temperature\":8.5,\"pressure\":898.75,\"density\":1.0625,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_heading_update_state_gnss_velocity_stale` (tests/vectors/mip/filter_data_13_51.yaml:137)
#[test]
fn case_filter_heading_update_state_gnss_velocity_stale() {
    check(
        "7565820e0e14c04000003e800000000200004cdf",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":20,\"name\":\"heading_update_state\",\"values\":{\"heading\":-3.0,\"heading_uncertainty\":0.25,\"source\":2,\"valid_flags\":0}}]}",
        ],
        false,
    );
}

/// `filter_mag_auto_hard_soft_iron` (tests/vectors/mip/filter_data_13_51.yaml:158)
#[test]
fn case_filter_mag_auto_hard_soft_iron() {
    check(
        "7565827010253e000000bd8000003e800000000110283c0000003c0000003c800000000128263f8000003c80000000000000bc8000003f7800000000000000000000000000003f840000000128293b0000003b0000003b0000003b8000003b8000003b8000003c0000003c0000003c00000000000fb2",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":37,\"name\":\"mag_auto_hard_iron_offset\",\"values\":{\"hard_iron_offset\":[0.125,-0.0625,0.25],\"valid_flags\":1}},{\"descriptor\":40,\"name\":\"mag_auto_hard_iron_offset_uncertainty\",\"values\":{\"hard_iron_offset_uncertainty\":[0.0078125,0.0078125,0.015625],\"valid_flags\":1}},{\"descriptor\":38,\"name\":\"mag_auto_soft_iron_matrix\",\"values\":{\"soft_iron_matrix\":[1.0,0.015625,0.0,-0.015625,0.96875,0.0,0.0,0.0,1.03125],\"valid_flags\":1}},{\"descriptor\":41,\"name\":\"mag_auto_soft_iron_matrix_uncertainty\",\"values\":{\"soft_iron_matrix_uncertainty\":[0.001953125,0.001953125,0.001953125,0.00390625,0.00390625,0.00390625,0.0078125,0.0078125,0.0078125],\"valid_flags\":0}}]}",
        ],
        false,
    );
}

/// `filter_gnss_antenna_offset_correction` (tests/vectors/mip/filter_data_13_51.yaml:207)
#[test]
fn case_filter_gnss_antenna_offset_correction() {
    check(
        "7565822010303f000000be8000003f900000000110313d8000003d8000003e000000000002fb",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":48,\"name\":\"gnss_antenna_offset_correction\",\"values\":{\"offset\":[0.5,-0.25,1.125],\"valid_flags\":1}},{\"descriptor\":49,\"name\":\"gnss_antenna_offset_correction_uncertainty\",\"values\":{\"offset_uncertainty\":[0.0625,0.0625,0.125],\"valid_flags\":0}}]}",
        ],
        false,
    );
}

/// `filter_multi_antenna_offset_correction_two_receivers` (tests/vectors/mip/filter_data_13_51.yaml:234)
#[test]
fn case_filter_multi_antenna_offset_correction_two_receivers() {
    check(
        "756582441134013d000000bd800000000000000001113402be0000003e8000003f00000000001135013c8000003c8000003d00000000011135023e8000003e8000003f000000000063a9",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":52,\"name\":\"multi_antenna_offset_correction\",\"values\":{\"receiver_id\":1,\"offset\":[0.03125,-0.0625,0.0],\"valid_flags\":1}},{\"descriptor\":52,\"name\":\"multi_antenna_offset_correction\",\"values\":{\"receiver_id\":2,\"offset\":[-0.125,0.25,0.5],\"valid_flags\":0}},{\"descriptor\":53,\"name\":\"multi_antenna_offset_correction_uncertainty\",\"values\":{\"receiver_id\":1,\"offset_uncertainty\":[0.015625,0.015625,0.03125],\"valid_flags\":1}},{\"descriptor\":53,\"name\":\"multi_antenna_offset_correction_uncertainty\",\"values\":{\"receiver_id\":2,\"offset_uncertainty\":[0.25,0.25,0.5],\"valid_flags\":0}}]}",
        ],
        false,
    );
}

/// `filter_ecef_and_relative_position_velocity` (tests/vectors/mip/filter_data_13_51.yaml:282)
#[test]
fn case_filter_ecef_and_relative_position_velocity() {
    check(
        "756582681c40c133a8ce80000000c152030850000000414f1e10e0000000000110413fc00000be80000000000000000110363fa000003fa0000040200000000110373d8000003d8000003e00000000001c424059200000000000c039400000000000400000000000000000019b63",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":64,\"name\":\"ecef_position\",\"values\":{\"position\":[-1288398.5,-4721697.25,4078625.75],\"valid_flags\":1}},{\"descriptor\":65,\"name\":\"ecef_velocity\",\"values\":{\"velocity\":[1.5,-0.25,0.0],\"valid_flags\":1}},{\"descriptor\":54,\"name\":\"ecef_position_uncertainty\",\"values\":{\"position_uncertainty\":[1.25,1.25,2.5],\"valid_flags\":1}},{\"descriptor\":55,\"name\":\"ecef_velocity_uncertainty\",\"values\":{\"velocity_uncertainty\":[0.0625,0.0625,0.125],\"valid_flags\":0}},{\"descriptor\":66,\"name\":\"ned_relative_position\",\"values\":{\"relative_position\":[100.5,-25.25,2.0],\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_aiding_status_summary_dual_antenna_odometer` (tests/vectors/mip/filter_data_13_51.yaml:336)
#[test]
fn case_filter_aiding_status_summary_dual_antenna_odometer() {
    check(
        "7565824611430148a8c010095e0000000000000000094648a8c010000103094648a8c01001310d134948a8c0103f4000003c800000020007000108473c800000000108483b8000000001f8b3",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":67,\"name\":\"gnss_position_aiding_status\",\"values\":{\"receiver_id\":1,\"time_of_week\":345600.5,\"status\":2398,\"reserved\":[0,0,0,0,0,0,0,0]}},{\"descriptor\":70,\"name\":\"aiding_measurement_summary\",\"values\":{\"time_of_week\":345600.5,\"source\":0,\"type\":1,\"indicator\":3}},{\"descriptor\":70,\"name\":\"aiding_measurement_summary\",\"values\":{\"time_of_week\":345600.5,\"source\":1,\"type\":49,\"indicator\":13}},{\"descriptor\":73,\"name\":\"gnss_dual_antenna_status\",\"values\":{\"time_of_week\":345600.5,\"heading\":0.75,\"heading_uncertainty\":0.015625,\"fix_type\":2,\"status_flags\":7,\"valid_flags\":1}},{\"descriptor\":71,\"name\":\"odometer_scale_factor_error\",\"values\":{\"scale_factor_error\":0.015625,\"valid_flags\":1}},{\"descriptor\":72,\"name\":\"odometer_scale_factor_error_uncertainty\",\"values\":{\"scale_factor_error_uncertainty\":0.00390625,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `filter_gnss_aiding_status_no_fix_config_error` (tests/vectors/mip/filter_data_13_51.yaml:409)
#[test]
fn case_filter_gnss_aiding_status_no_fix_config_error() {
    check(
        "7565822d11430200000000c00100000000000000000946000000000006301349000000000000000000000000000001000082ef",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":67,\"name\":\"gnss_position_aiding_status\",\"values\":{\"receiver_id\":2,\"time_of_week\":0.0,\"status\":49153,\"reserved\":[0,0,0,0,0,0,0,0]}},{\"descriptor\":70,\"name\":\"aiding_measurement_summary\",\"values\":{\"time_of_week\":0.0,\"source\":0,\"type\":6,\"indicator\":48}},{\"descriptor\":73,\"name\":\"gnss_dual_antenna_status\",\"values\":{\"time_of_week\":0.0,\"heading\":0.0,\"heading_uncertainty\":0.0,\"fix_type\":0,\"status_flags\":1,\"valid_flags\":0}}]}",
        ],
        false,
    );
}

/// `filter_aiding_frame_config_error` (tests/vectors/mip/filter_data_13_51.yaml:455)
#[test]
fn case_filter_aiding_frame_config_error() {
    check(
        "7565823a1f50013e000000be800000000000003f000000bf0000003f0000003f0000001b51013d8000003d8000003d0000003c0000003c0000003c80000056fb",
        None,
        &[
            "{\"offset\":0,\"set\":130,\"fields\":[{\"descriptor\":80,\"name\":\"aiding_frame_config_error\",\"values\":{\"frame_id\":1,\"translation\":[0.125,-0.25,0.0],\"attitude\":[0.5,-0.5,0.5,0.5]}},{\"descriptor\":81,\"name\":\"aiding_frame_config_error_uncertainty\",\"values\":{\"frame_id\":1,\"translation_uncertainty\":[0.0625,0.0625,0.03125],\"attitude_uncertainty\":[0.0078125,0.0078125,0.015625]}}]}",
        ],
        false,
    );
}

/// `receiver_info_command` (tests/vectors/mip/gnss.yaml:7)
#[test]
fn case_receiver_info_command() {
    check(
        "75650e020201edfa",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":1,\"name\":\"receiver_info\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `receiver_info_reply_two_receivers` (tests/vectors/mip/gnss.yaml:17)
#[test]
fn case_receiver_info_reply_two_receivers() {
    check(
        "75650e4b04f1010047810201915a45442d4639502c48504720312e33320000000000000000000000000000000002925a45442d4639502c48504720312e333200000000000000000000000000000000b5ca",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"receiver_info_response\",\"values\":{\"num_receivers\":2,\"receiver_info\":[{\"receiver_id\":1,\"mip_data_descriptor_set\":145,\"description\":\"ZED-F9P,HPG 1.32\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\"},{\"receiver_id\":2,\"mip_data_descriptor_set\":146,\"description\":\"ZED-F9P,HPG 1.32\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\"}]}}]}",
        ],
        false,
    );
}

/// `receiver_info_reply_none` (tests/vectors/mip/gnss.yaml:44)
#[test]
fn case_receiver_info_reply_none() {
    check(
        "75650e0704f101000381006981",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"receiver_info_response\",\"values\":{\"num_receivers\":0,\"receiver_info\":[]}}]}",
        ],
        false,
    );
}

/// `signal_configuration_write` (tests/vectors/mip/gnss.yaml:57)
#[test]
fn case_signal_configuration_write() {
    check(
        "75650e0b0b020105010505000000001197",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":2,\"name\":\"signal_configuration\",\"values\":{\"function\":1,\"gps_enable\":5,\"glonass_enable\":1,\"galileo_enable\":5,\"beidou_enable\":5,\"reserved\":[0,0,0,0]}}]}",
        ],
        false,
    );
}

/// `signal_configuration_write_every_bit` (tests/vectors/mip/gnss.yaml:79)
#[test]
fn case_signal_configuration_write_every_bit() {
    check(
        "75650e0b0b0201070307070000000019cb",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":2,\"name\":\"signal_configuration\",\"values\":{\"function\":1,\"gps_enable\":7,\"glonass_enable\":3,\"galileo_enable\":7,\"beidou_enable\":7,\"reserved\":[0,0,0,0]}}]}",
        ],
        false,
    );
}

/// `signal_configuration_read` (tests/vectors/mip/gnss.yaml:100)
#[test]
fn case_signal_configuration_read() {
    check(
        "75650e03030202f2f2",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":2,\"name\":\"signal_configuration\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `signal_configuration_read_reply` (tests/vectors/mip/gnss.yaml:110)
#[test]
fn case_signal_configuration_read_reply() {
    check(
        "75650e0e04f102000a820100050100000000804f",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":2,\"ack_code\":0}},{\"descriptor\":130,\"name\":\"signal_configuration_response\",\"values\":{\"gps_enable\":1,\"glonass_enable\":0,\"galileo_enable\":5,\"beidou_enable\":1,\"reserved\":[0,0,0,0]}}]}",
        ],
        false,
    );
}

/// `signal_configuration_save` (tests/vectors/mip/gnss.yaml:126)
#[test]
fn case_signal_configuration_save() {
    check(
        "75650e03030203f3f3",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":2,\"name\":\"signal_configuration\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `signal_configuration_load` (tests/vectors/mip/gnss.yaml:135)
#[test]
fn case_signal_configuration_load() {
    check(
        "75650e03030204f4f4",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":2,\"name\":\"signal_configuration\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `signal_configuration_default` (tests/vectors/mip/gnss.yaml:144)
#[test]
fn case_signal_configuration_default() {
    check(
        "75650e03030205f5f5",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":2,\"name\":\"signal_configuration\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `spartn_configuration_write_lband` (tests/vectors/mip/gnss.yaml:153)
#[test]
fn case_spartn_configuration_write_lband() {
    check(
        "75650e51512001010200000000000030313031303130313031303130313031303130313031303130313031303130310000000000003031303130313031303130313031303130313031303130313031303130313031ceb1",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":32,\"name\":\"spartn_configuration\",\"values\":{\"function\":1,\"enable\":1,\"type\":2,\"current_key_tow\":0,\"current_key_week\":0,\"current_key\":\"01010101010101010101010101010101\",\"next_key_tow\":0,\"next_key_week\":0,\"next_key\":\"01010101010101010101010101010101\"}}]}",
        ],
        false,
    );
}

/// `spartn_configuration_write_network` (tests/vectors/mip/gnss.yaml:186)
#[test]
fn case_spartn_configuration_write_network() {
    check(
        "75650e51512001010100054600091a30313233343536373839414243444546303132333435363738394142434445460007e900091b4645444342413938373635343332313046454443424139383736353433323130b7c5",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":32,\"name\":\"spartn_configuration\",\"values\":{\"function\":1,\"enable\":1,\"type\":1,\"current_key_tow\":345600,\"current_key_week\":2330,\"current_key\":\"0123456789ABCDEF0123456789ABCDEF\",\"next_key_tow\":518400,\"next_key_week\":2331,\"next_key\":\"FEDCBA9876543210FEDCBA9876543210\"}}]}",
        ],
        false,
    );
}

/// `spartn_configuration_ack` (tests/vectors/mip/gnss.yaml:216)
#[test]
fn case_spartn_configuration_ack() {
    check(
        "75650e0404f1200001f6",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":32,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `spartn_configuration_read` (tests/vectors/mip/gnss.yaml:225)
#[test]
fn case_spartn_configuration_read() {
    check(
        "75650e03032002102e",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":32,\"name\":\"spartn_configuration\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `spartn_configuration_read_reply` (tests/vectors/mip/gnss.yaml:234)
#[test]
fn case_spartn_configuration_read_reply() {
    check(
        "75650e5404f1200050a0010200000000000030313031303130313031303130313031303130313031303130313031303130310000000000003031303130313031303130313031303130313031303130313031303130313031647e",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":32,\"ack_code\":0}},{\"descriptor\":160,\"name\":\"spartn_configuration_response\",\"values\":{\"enable\":1,\"type\":2,\"current_key_tow\":0,\"current_key_week\":0,\"current_key\":\"01010101010101010101010101010101\",\"next_key_tow\":0,\"next_key_week\":0,\"next_key\":\"01010101010101010101010101010101\"}}]}",
        ],
        false,
    );
}

/// `spartn_configuration_save` (tests/vectors/mip/gnss.yaml:263)
#[test]
fn case_spartn_configuration_save() {
    check(
        "75650e03032003112f",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":32,\"name\":\"spartn_configuration\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `spartn_configuration_default` (tests/vectors/mip/gnss.yaml:272)
#[test]
fn case_spartn_configuration_default() {
    check(
        "75650e030320051331",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":32,\"name\":\"spartn_configuration\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `gx5_gnss_llh_ecef_position` (tests/vectors/mip/gnss_data.yaml:8)
#[test]
fn case_gx5_gnss_llh_ecef_position() {
    check(
        "7565814c2c034046c00000000000c057500000000000407008000000000040720c00000000003fc0000040100000001f2004c110000200000000c1520000100000004151400008000000406000000003fe78",
        None,
        &[
            "{\"offset\":0,\"set\":129,\"fields\":[{\"descriptor\":3,\"name\":\"llh_position\",\"values\":{\"latitude\":45.5,\"longitude\":-93.25,\"ellipsoid_height\":256.5,\"msl_height\":288.75,\"horizontal_accuracy\":1.5,\"vertical_accuracy\":2.25,\"valid_flags\":31}},{\"descriptor\":4,\"name\":\"ecef_position\",\"values\":{\"position\":[-262144.5,-4718592.25,4521984.125],\"position_accuracy\":3.5,\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `gx5_gnss_velocity_dop` (tests/vectors/mip/gnss_data.yaml:38)
#[test]
fn case_gx5_gnss_velocity_dop() {
    check(
        "7565815824053fc00000be8000003e0000003fc800003fc0000043af40003e80000040200000001b14063f000000bfa000003f4000003ec00000000120073fe000003fc000003f6000003fa000003f4000003f2000003f000000007f5dd1",
        None,
        &[
            "{\"offset\":0,\"set\":129,\"fields\":[{\"descriptor\":5,\"name\":\"ned_velocity\",\"values\":{\"velocity\":[1.5,-0.25,0.125],\"speed\":1.5625,\"ground_speed\":1.5,\"heading\":350.5,\"speed_accuracy\":0.25,\"heading_accuracy\":2.5,\"valid_flags\":27}},{\"descriptor\":6,\"name\":\"ecef_velocity\",\"values\":{\"velocity\":[0.5,-1.25,0.75],\"velocity_accuracy\":0.375,\"valid_flags\":1}},{\"descriptor\":7,\"name\":\"dop\",\"values\":{\"gdop\":1.75,\"pdop\":1.5,\"hdop\":0.875,\"vdop\":1.25,\"tdop\":0.75,\"ndop\":0.625,\"edop\":0.5,\"valid_flags\":127}}]}",
        ],
        false,
    );
}

/// `gx5_gnss_time_clock` (tests/vectors/mip/gnss_data.yaml:74)
#[test]
fn case_gx5_gnss_time_clock() {
    check(
        "756581390f0807e8021d173b3a000002ee00030e09411518020000000008ff00031c0a3f50000000000000bec00000000000003f0000000000000000074207",
        None,
        &[
            "{\"offset\":0,\"set\":129,\"fields\":[{\"descriptor\":8,\"name\":\"utc_time\",\"values\":{\"year\":2024,\"month\":2,\"day\":29,\"hour\":23,\"minute\":59,\"second\":58,\"millisecond\":750,\"valid_flags\":3}},{\"descriptor\":9,\"name\":\"gps_time\",\"values\":{\"tow\":345600.5,\"week_number\":2303,\"valid_flags\":3}},{\"descriptor\":10,\"name\":\"clock_info\",\"values\":{\"bias\":0.0009765625,\"drift\":-1.9073486328125e-06,\"accuracy_estimate\":3.0517578125e-05,\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `gx5_gnss_fix_hardware_status` (tests/vectors/mip/gnss_data.yaml:108)
#[test]
fn case_gx5_gnss_fix_hardware_status() {
    check(
        "7565810f080b000900010007070d0104010007afa8",
        None,
        &[
            "{\"offset\":0,\"set\":129,\"fields\":[{\"descriptor\":11,\"name\":\"fix_info\",\"values\":{\"fix_type\":0,\"num_sv\":9,\"fix_flags\":1,\"valid_flags\":7}},{\"descriptor\":13,\"name\":\"hardware_status\",\"values\":{\"receiver_state\":1,\"antenna_state\":4,\"antenna_power\":1,\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `gx5_gnss_fix_time_only_antenna_open` (tests/vectors/mip/gnss_data.yaml:132)
#[test]
fn case_gx5_gnss_fix_time_only_antenna_open() {
    check(
        "7565810f080b020100020003070d0203000006a449",
        None,
        &[
            "{\"offset\":0,\"set\":129,\"fields\":[{\"descriptor\":11,\"name\":\"fix_info\",\"values\":{\"fix_type\":2,\"num_sv\":1,\"fix_flags\":2,\"valid_flags\":3}},{\"descriptor\":13,\"name\":\"hardware_status\",\"values\":{\"receiver_state\":2,\"antenna_state\":3,\"antenna_power\":0,\"valid_flags\":6}}]}",
        ],
        false,
    );
}

/// `gx5_gnss_sv_info_two_entries` (tests/vectors/mip/gnss_data.yaml:156)
#[test]
fn case_gx5_gnss_sv_info_two_entries() {
    check(
        "7565811c0e0c010c002d010e00230003007b0e0c02190020002dfffb0002007b74c7",
        None,
        &[
            "{\"offset\":0,\"set\":129,\"fields\":[{\"descriptor\":12,\"name\":\"sv_info\",\"values\":{\"channel\":1,\"sv_id\":12,\"carrier_to_noise_ratio\":45,\"azimuth\":270,\"elevation\":35,\"sv_flags\":3,\"valid_flags\":123}},{\"descriptor\":12,\"name\":\"sv_info\",\"values\":{\"channel\":2,\"sv_id\":25,\"carrier_to_noise_ratio\":32,\"azimuth\":45,\"elevation\":-5,\"sv_flags\":2,\"valid_flags\":123}}]}",
        ],
        false,
    );
}

/// `gx5_gnss_dgnss_info_and_channels` (tests/vectors/mip/gnss_data.yaml:183)
#[test]
fn case_gx5_gnss_dgnss_info_and_channels() {
    check(
        "756581300e0e4020000003ff00020002000f110f0c40200000c07000003e000000000f110f194040000041280000bd80000000078b31",
        None,
        &[
            "{\"offset\":0,\"set\":129,\"fields\":[{\"descriptor\":14,\"name\":\"dgnss_info\",\"values\":{\"newest_age\":2.5,\"base_station_id\":1023,\"base_station_status\":2,\"num_channels\":2,\"valid_flags\":15}},{\"descriptor\":15,\"name\":\"dgnss_channel_status\",\"values\":{\"sv_id\":12,\"age\":2.5,\"pseudorange_correction\":-3.75,\"pseudorange_rate_correction\":0.125,\"valid_flags\":15}},{\"descriptor\":15,\"name\":\"dgnss_channel_status\",\"values\":{\"sv_id\":25,\"age\":3.0,\"pseudorange_correction\":10.5,\"pseudorange_rate_correction\":-0.0625,\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_1_satellite_status_two_fields` (tests/vectors/mip/gnss_observations.yaml:8)
#[test]
fn case_gnss_receiver_1_satellite_status_two_fields() {
    check(
        "756591361b200102411518020000000008fc010c423600004387200001007f1b200202411518020000000008fc03074120000042b4400000003fd5ee",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":32,\"name\":\"satellite_status\",\"values\":{\"index\":1,\"count\":2,\"tow\":345600.5,\"week_number\":2300,\"gnss_id\":1,\"satellite_id\":12,\"elevation\":45.5,\"azimuth\":270.25,\"health\":true,\"valid_flags\":127}},{\"descriptor\":32,\"name\":\"satellite_status\",\"values\":{\"index\":2,\"count\":2,\"tow\":345600.5,\"week_number\":2300,\"gnss_id\":3,\"satellite_id\":7,\"elevation\":10.0,\"azimuth\":90.125,\"health\":false,\"valid_flags\":63}}]}",
        ],
        false,
    );
}

/// `gnss_external_satellite_status` (tests/vectors/mip/gnss_observations.yaml:58)
#[test]
fn case_gnss_external_satellite_status() {
    check(
        "7565941b1b20010140f518040000000008fd0215427300004334000001007fdf60",
        None,
        &[
            "{\"offset\":0,\"set\":148,\"fields\":[{\"descriptor\":32,\"name\":\"satellite_status\",\"values\":{\"index\":1,\"count\":1,\"tow\":86400.25,\"week_number\":2301,\"gnss_id\":2,\"satellite_id\":21,\"elevation\":60.75,\"azimuth\":180.0,\"health\":true,\"valid_flags\":127}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_1_raw` (tests/vectors/mip/gnss_observations.yaml:90)
#[test]
fn case_gnss_receiver_1_raw() {
    check(
        "7565913f3f220101411518020000000008fc000105010c0d422a0000054174403872000000419a9ac519000000c49a50003f4000003c8000003e00000041480000ffffb219",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":34,\"name\":\"raw\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.5,\"week_number\":2300,\"receiver_id\":1,\"tracking_channel\":5,\"gnss_id\":1,\"satellite_id\":12,\"signal_id\":13,\"signal_strength\":42.5,\"quality\":5,\"pseudorange\":21234567.125,\"carrier_phase\":111587654.25,\"doppler\":-1234.5,\"range_uncert\":0.75,\"phase_uncert\":0.015625,\"doppler_uncert\":0.125,\"lock_time\":12.5,\"valid_flags\":65535}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_2_satellite_status_and_raw` (tests/vectors/mip/gnss_observations.yaml:136)
#[test]
fn case_gnss_receiver_2_satellite_status_and_raw() {
    check(
        "756592991b200101411fa4000000000008fb041ec020000043b3c00000000e3f220102411fa4000000000008fb00020001030e42190000044174fb18080000000000000000000000440000003fc00000000000003e800000000000005bff3f220202411fa4000000000008fb040011041ea90000000001000000000000000000000000000000000000000000000000000000000000000000000000017fe53c",
        None,
        &[
            "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":32,\"name\":\"satellite_status\",\"values\":{\"index\":1,\"count\":1,\"tow\":518400.0,\"week_number\":2299,\"gnss_id\":4,\"satellite_id\":30,\"elevation\":-2.5,\"azimuth\":359.5,\"health\":false,\"valid_flags\":14}},{\"descriptor\":34,\"name\":\"raw\",\"values\":{\"index\":1,\"count\":2,\"tow\":518400.0,\"week_number\":2299,\"receiver_id\":2,\"tracking_channel\":0,\"gnss_id\":1,\"satellite_id\":3,\"signal_id\":14,\"signal_strength\":38.25,\"quality\":4,\"pseudorange\":22000000.5,\"carrier_phase\":0.0,\"doppler\":512.0,\"range_uncert\":1.5,\"phase_uncert\":0.0,\"doppler_uncert\":0.25,\"lock_time\":0.0,\"valid_flags\":23551}},{\"descriptor\":34,\"name\":\"raw\",\"values\":{\"index\":2,\"count\":2,\"tow\":518400.0,\"week_number\":2299,\"receiver_id\":1024,\"tracking_channel\":17,\"gnss_id\":4,\"satellite_id\":30,\"signal_id\":169,\"signal_strength\":0.0,\"quality\":1,\"pseudorange\":0.0,\"carrier_phase\":0.0,\"doppler\":0.0,\"range_uncert\":0.0,\"phase_uncert\":0.0,\"doppler_uncert\":0.0,\"lock_time\":0.0,\"valid_flags\":383}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_1_gps_ephemeris` (tests/vectors/mip/gnss_observations.yaml:233)
#[test]
fn case_gnss_receiver_1_gps_ephemeris() {
    check(
        "756591dcdc610101411518000000000008fc05002d2d4115888000000000bf20000000000000bec00000000000000000000000000000beb000000000000000000000000000003ea00000000000004115888000000000417954600800000000000000000000003ff40000000000003ed000000000000000000000000000003f80000000000000bff80000000000004006000000000000bee00000000000003fef0000000000003e900000000000003eb8000000000000bec80000000000003f00000000000000bf100000000000004067700000000000c0344000000000000003a155",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":97,\"name\":\"gps_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":5,\"health\":0,\"iodc\":45,\"iode\":45,\"t_oc\":352800.0,\"af0\":-0.0001220703125,\"af1\":-1.9073486328125e-06,\"af2\":0.0,\"t_gd\":-9.5367431640625e-07,\"isc_l1ca\":0.0,\"isc_l2c\":4.76837158203125e-07,\"t_oe\":352800.0,\"a\":26560000.5,\"a_dot\":0.0,\"mean_anomaly\":1.25,\"delta_mean_motion\":3.814697265625e-06,\"delta_mean_motion_dot\":0.0,\"eccentricity\":0.0078125,\"argument_of_perigee\":-1.5,\"omega\":2.75,\"omega_dot\":-7.62939453125e-06,\"inclination\":0.96875,\"inclination_dot\":2.384185791015625e-07,\"c_ic\":1.430511474609375e-06,\"c_is\":-2.86102294921875e-06,\"c_uc\":3.0517578125e-05,\"c_us\":-6.103515625e-05,\"c_rc\":187.5,\"c_rs\":-20.25,\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_1_glonass_ephemeris` (tests/vectors/mip/gnss_observations.yaml:306)
#[test]
fn case_gnss_receiver_1_glonass_ephemeris() {
    check(
        "7565916868620101411518000000000008fc03fc0000a8c00000ac4401be90000000000000bf1000000000000041678c29d0000000c162d687e800000041721eac00000000449a5000c52be400440008000000000035800000b60000000001c8b580000002001e010101000173f2",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":98,\"name\":\"glonass_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":3,\"freq_number\":-4,\"tk\":43200,\"tb\":44100,\"sat_type\":1,\"gamma\":-2.384185791015625e-07,\"tau_n\":-6.103515625e-05,\"x\":[12345678.5,-9876543.25,19000000.0],\"v\":[1234.5,-2750.25,512.125],\"a\":[0.0,9.5367431640625e-07,-1.9073486328125e-06],\"health\":0,\"p\":1,\"nt\":200,\"delta_tau_n\":-9.5367431640625e-07,\"ft\":2,\"en\":0,\"p1\":30,\"p2\":1,\"p3\":1,\"p4\":1,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_1_galileo_ephemeris` (tests/vectors/mip/gnss_observations.yaml:361)
#[test]
fn case_gnss_receiver_1_galileo_ephemeris() {
    check(
        "756591dcdc630101411518000000000008fc13002d2d4115888000000000bf20000000000000bec00000000000000000000000000000beb000000000000000000000000000003ea00000000000004115888000000000417954600800000000000000000000003ff40000000000003ed000000000000000000000000000003f80000000000000bff80000000000004006000000000000bee00000000000003fef0000000000003e900000000000003eb8000000000000bec80000000000003f00000000000000bf100000000000004067700000000000c0344000000000000001af4d",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":99,\"name\":\"galileo_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":19,\"health\":0,\"iodc\":45,\"iode\":45,\"t_oc\":352800.0,\"af0\":-0.0001220703125,\"af1\":-1.9073486328125e-06,\"af2\":0.0,\"t_gd\":-9.5367431640625e-07,\"isc_l1ca\":0.0,\"isc_l2c\":4.76837158203125e-07,\"t_oe\":352800.0,\"a\":26560000.5,\"a_dot\":0.0,\"mean_anomaly\":1.25,\"delta_mean_motion\":3.814697265625e-06,\"delta_mean_motion_dot\":0.0,\"eccentricity\":0.0078125,\"argument_of_perigee\":-1.5,\"omega\":2.75,\"omega_dot\":-7.62939453125e-06,\"inclination\":0.96875,\"inclination_dot\":2.384185791015625e-07,\"c_ic\":1.430511474609375e-06,\"c_is\":-2.86102294921875e-06,\"c_uc\":3.0517578125e-05,\"c_us\":-6.103515625e-05,\"c_rc\":187.5,\"c_rs\":-20.25,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_1_beidou_ephemeris` (tests/vectors/mip/gnss_observations.yaml:432)
#[test]
fn case_gnss_receiver_1_beidou_ephemeris() {
    check(
        "756591dcdc640101411518000000000008fc08002d2d4115888000000000bf20000000000000bec00000000000000000000000000000beb000000000000000000000000000003ea00000000000004115888000000000417954600800000000000000000000003ff40000000000003ed000000000000000000000000000003f80000000000000bff80000000000004006000000000000bee00000000000003fef0000000000003e900000000000003eb8000000000000bec80000000000003f00000000000000bf100000000000004067700000000000c0344000000000000007ab54",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":100,\"name\":\"beidou_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":8,\"health\":0,\"iodc\":45,\"iode\":45,\"t_oc\":352800.0,\"af0\":-0.0001220703125,\"af1\":-1.9073486328125e-06,\"af2\":0.0,\"t_gd\":-9.5367431640625e-07,\"isc_l1ca\":0.0,\"isc_l2c\":4.76837158203125e-07,\"t_oe\":352800.0,\"a\":26560000.5,\"a_dot\":0.0,\"mean_anomaly\":1.25,\"delta_mean_motion\":3.814697265625e-06,\"delta_mean_motion_dot\":0.0,\"eccentricity\":0.0078125,\"argument_of_perigee\":-1.5,\"omega\":2.75,\"omega_dot\":-7.62939453125e-06,\"inclination\":0.96875,\"inclination_dot\":2.384185791015625e-07,\"c_ic\":1.430511474609375e-06,\"c_is\":-2.86102294921875e-06,\"c_uc\":3.0517578125e-05,\"c_us\":-6.103515625e-05,\"c_rc\":187.5,\"c_rs\":-20.25,\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_2_gps_ephemeris` (tests/vectors/mip/gnss_observations.yaml:503)
#[test]
fn case_gnss_receiver_2_gps_ephemeris() {
    check(
        "756592dcdc610101411518000000000008fc09002d2d4115888000000000bf20000000000000bec00000000000000000000000000000beb000000000000000000000000000003ea00000000000004115888000000000417954600800000000000000000000003ff40000000000003ed000000000000000000000000000003f80000000000000bff80000000000004006000000000000bee00000000000003fef0000000000003e900000000000003eb8000000000000bec80000000000003f00000000000000bf100000000000004067700000000000c0344000000000000007aa6f",
        None,
        &[
            "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":97,\"name\":\"gps_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":9,\"health\":0,\"iodc\":45,\"iode\":45,\"t_oc\":352800.0,\"af0\":-0.0001220703125,\"af1\":-1.9073486328125e-06,\"af2\":0.0,\"t_gd\":-9.5367431640625e-07,\"isc_l1ca\":0.0,\"isc_l2c\":4.76837158203125e-07,\"t_oe\":352800.0,\"a\":26560000.5,\"a_dot\":0.0,\"mean_anomaly\":1.25,\"delta_mean_motion\":3.814697265625e-06,\"delta_mean_motion_dot\":0.0,\"eccentricity\":0.0078125,\"argument_of_perigee\":-1.5,\"omega\":2.75,\"omega_dot\":-7.62939453125e-06,\"inclination\":0.96875,\"inclination_dot\":2.384185791015625e-07,\"c_ic\":1.430511474609375e-06,\"c_is\":-2.86102294921875e-06,\"c_uc\":3.0517578125e-05,\"c_us\":-6.103515625e-05,\"c_rc\":187.5,\"c_rs\":-20.25,\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_2_glonass_ephemeris` (tests/vectors/mip/gnss_observations.yaml:576)
#[test]
fn case_gnss_receiver_2_glonass_ephemeris() {
    check(
        "7565926868620101411518000000000008fc04fc0000a8c00000ac4401be90000000000000bf1000000000000041678c29d0000000c162d687e800000041721eac00000000449a5000c52be400440008000000000035800000b60000000001c8b580000002001e010101000175b6",
        None,
        &[
            "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":98,\"name\":\"glonass_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":4,\"freq_number\":-4,\"tk\":43200,\"tb\":44100,\"sat_type\":1,\"gamma\":-2.384185791015625e-07,\"tau_n\":-6.103515625e-05,\"x\":[12345678.5,-9876543.25,19000000.0],\"v\":[1234.5,-2750.25,512.125],\"a\":[0.0,9.5367431640625e-07,-1.9073486328125e-06],\"health\":0,\"p\":1,\"nt\":200,\"delta_tau_n\":-9.5367431640625e-07,\"ft\":2,\"en\":0,\"p1\":30,\"p2\":1,\"p3\":1,\"p4\":1,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_2_galileo_ephemeris` (tests/vectors/mip/gnss_observations.yaml:631)
#[test]
fn case_gnss_receiver_2_galileo_ephemeris() {
    check(
        "756592dcdc630101411518000000000008fc0b002d2d4115888000000000bf20000000000000bec00000000000000000000000000000beb000000000000000000000000000003ea00000000000004115888000000000417954600800000000000000000000003ff40000000000003ed000000000000000000000000000003f80000000000000bff80000000000004006000000000000bee00000000000003fef0000000000003e900000000000003eb8000000000000bec80000000000003f00000000000000bf100000000000004067700000000000c0344000000000000005acbf",
        None,
        &[
            "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":99,\"name\":\"galileo_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":11,\"health\":0,\"iodc\":45,\"iode\":45,\"t_oc\":352800.0,\"af0\":-0.0001220703125,\"af1\":-1.9073486328125e-06,\"af2\":0.0,\"t_gd\":-9.5367431640625e-07,\"isc_l1ca\":0.0,\"isc_l2c\":4.76837158203125e-07,\"t_oe\":352800.0,\"a\":26560000.5,\"a_dot\":0.0,\"mean_anomaly\":1.25,\"delta_mean_motion\":3.814697265625e-06,\"delta_mean_motion_dot\":0.0,\"eccentricity\":0.0078125,\"argument_of_perigee\":-1.5,\"omega\":2.75,\"omega_dot\":-7.62939453125e-06,\"inclination\":0.96875,\"inclination_dot\":2.384185791015625e-07,\"c_ic\":1.430511474609375e-06,\"c_is\":-2.86102294921875e-06,\"c_uc\":3.0517578125e-05,\"c_us\":-6.103515625e-05,\"c_rc\":187.5,\"c_rs\":-20.25,\"valid_flags\":5}}]}",
        ],
        false,
    );
}

/// `gnss_receiver_2_beidou_ephemeris` (tests/vectors/mip/gnss_observations.yaml:702)
#[test]
fn case_gnss_receiver_2_beidou_ephemeris() {
    check(
        "756592dcdc640101411518000000000008fc1b002d2d4115888000000000bf20000000000000bec00000000000000000000000000000beb000000000000000000000000000003ea00000000000004115888000000000417954600800000000000000000000003ff40000000000003ed000000000000000000000000000003f80000000000000bff80000000000004006000000000000bee00000000000003fef0000000000003e900000000000003eb8000000000000bec80000000000003f00000000000000bf100000000000004067700000000000c0344000000000000000b875",
        None,
        &[
            "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":100,\"name\":\"beidou_ephemeris\",\"values\":{\"index\":1,\"count\":1,\"tow\":345600.0,\"week_number\":2300,\"satellite_id\":27,\"health\":0,\"iodc\":45,\"iode\":45,\"t_oc\":352800.0,\"af0\":-0.0001220703125,\"af1\":-1.9073486328125e-06,\"af2\":0.0,\"t_gd\":-9.5367431640625e-07,\"isc_l1ca\":0.0,\"isc_l2c\":4.76837158203125e-07,\"t_oe\":352800.0,\"a\":26560000.5,\"a_dot\":0.0,\"mean_anomaly\":1.25,\"delta_mean_motion\":3.814697265625e-06,\"delta_mean_motion_dot\":0.0,\"eccentricity\":0.0078125,\"argument_of_perigee\":-1.5,\"omega\":2.75,\"omega_dot\":-7.62939453125e-06,\"inclination\":0.96875,\"inclination_dot\":2.384185791015625e-07,\"c_ic\":1.430511474609375e-06,\"c_is\":-2.86102294921875e-06,\"c_uc\":3.0517578125e-05,\"c_us\":-6.103515625e-05,\"c_rc\":187.5,\"c_rs\":-20.25,\"valid_flags\":0}}]}",
        ],
        false,
    );
}

/// `cv7_gnss_receiver_1_position_velocity` (tests/vectors/mip/gnss_receivers.yaml:11)
#[test]
fn case_cv7_gnss_receiver_1_position_velocity() {
    check(
        "756591842c034046200000000000c052480000000000405c20000000000040622800000000003f4000003fa00000001f20044134f80080000000c150ed00300000004150ec40100000003fc0000000032405c02000003f0000000000000040200000402000004328c0003e00000040800000003f14063f800000c00000003e8000003e0000000003374f",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":3,\"name\":\"llh_position\",\"values\":{\"latitude\":44.25,\"longitude\":-73.125,\"ellipsoid_height\":112.5,\"msl_height\":145.25,\"horizontal_accuracy\":0.75,\"vertical_accuracy\":1.25,\"valid_flags\":31}},{\"descriptor\":4,\"name\":\"ecef_position\",\"values\":{\"position\":[1374208.5,-4436992.75,4436224.25],\"position_accuracy\":1.5,\"valid_flags\":3}},{\"descriptor\":5,\"name\":\"ned_velocity\",\"values\":{\"velocity\":[-2.5,0.5,0.0],\"speed\":2.5,\"ground_speed\":2.5,\"heading\":168.75,\"speed_accuracy\":0.125,\"heading_accuracy\":4.0,\"valid_flags\":63}},{\"descriptor\":6,\"name\":\"ecef_velocity\",\"values\":{\"velocity\":[1.0,-2.0,0.25],\"velocity_accuracy\":0.125,\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `cv7_gnss_receiver_2_dop_time_fix_status` (tests/vectors/mip/gnss_receivers.yaml:58)
#[test]
fn case_cv7_gnss_receiver_2_dop_time_fix_status() {
    check(
        "7565924c200740100000400000003f9000003fe000003f8000003f4000003f600000000f0f0807e90c1f0000010000007d00030e094115184880000000095f0003080b061500020007070d01020200070b4c",
        None,
        &[
            "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":7,\"name\":\"dop\",\"values\":{\"gdop\":2.25,\"pdop\":2.0,\"hdop\":1.125,\"vdop\":1.75,\"tdop\":1.0,\"ndop\":0.75,\"edop\":0.875,\"valid_flags\":15}},{\"descriptor\":8,\"name\":\"utc_time\",\"values\":{\"year\":2025,\"month\":12,\"day\":31,\"hour\":0,\"minute\":0,\"second\":1,\"millisecond\":125,\"valid_flags\":3}},{\"descriptor\":9,\"name\":\"gps_time\",\"values\":{\"tow\":345618.125,\"week_number\":2399,\"valid_flags\":3}},{\"descriptor\":11,\"name\":\"fix_info\",\"values\":{\"fix_type\":6,\"num_sv\":21,\"fix_flags\":2,\"valid_flags\":7}},{\"descriptor\":13,\"name\":\"hardware_status\",\"values\":{\"receiver_state\":1,\"antenna_state\":2,\"antenna_power\":2,\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `cv7_gnss_receiver_1_clock_leap_sbas` (tests/vectors/mip/gnss_receivers.yaml:106)
#[test]
fn case_cv7_gnss_receiver_1_clock_leap_sbas() {
    check(
        "7565913b2410bf200000000000003ea00000000000003ef00000000000003eb0000000000000000f05111200021212411518010000000008ff027b0707003f508a",
        None,
        &[
            "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":16,\"name\":\"clock_info_2\",\"values\":{\"bias\":-0.0001220703125,\"drift\":4.76837158203125e-07,\"bias_accuracy_estimate\":1.52587890625e-05,\"drift_accuracy_estimate\":9.5367431640625e-07,\"valid_flags\":15}},{\"descriptor\":17,\"name\":\"gps_leap_seconds\",\"values\":{\"leap_seconds\":18,\"valid_flags\":2}},{\"descriptor\":18,\"name\":\"sbas_info\",\"values\":{\"tow\":345600.25,\"week_number\":2303,\"sbas_system\":2,\"sbas_id\":123,\"count\":7,\"sbas_status\":7,\"valid_flags\":63}}]}",
        ],
        false,
    );
}

/// `cv7_gnss_external_nmea_fields` (tests/vectors/mip/gnss_receivers.yaml:143)
#[test]
fn case_cv7_gnss_external_nmea_fields() {
    check(
        "756594672c03c040f000000000004062e80000000000404e4000000000004043000000000000000000000000000000072405000000000000000000000000000000004090000042b400000000000000000000000c0f0807e9060f0c1e2d000001f40001080b070b00020007685e",
        None,
        &[
            "{\"offset\":0,\"set\":148,\"fields\":[{\"descriptor\":3,\"name\":\"llh_position\",\"values\":{\"latitude\":-33.875,\"longitude\":151.25,\"ellipsoid_height\":60.5,\"msl_height\":38.0,\"horizontal_accuracy\":0.0,\"vertical_accuracy\":0.0,\"valid_flags\":7}},{\"descriptor\":5,\"name\":\"ned_velocity\",\"values\":{\"velocity\":[0.0,0.0,0.0],\"speed\":0.0,\"ground_speed\":4.5,\"heading\":90.0,\"speed_accuracy\":0.0,\"heading_accuracy\":0.0,\"valid_flags\":12}},{\"descriptor\":8,\"name\":\"utc_time\",\"values\":{\"year\":2025,\"month\":6,\"day\":15,\"hour\":12,\"minute\":30,\"second\":45,\"millisecond\":500,\"valid_flags\":1}},{\"descriptor\":11,\"name\":\"fix_info\",\"values\":{\"fix_type\":7,\"num_sv\":11,\"fix_flags\":2,\"valid_flags\":7}}]}",
        ],
        false,
    );
}

/// `cv7_gnss_corrections_base_station_rtk_status` (tests/vectors/mip/gnss_receivers.yaml:189)
#[test]
fn case_cv7_gnss_corrections_base_station_rtk_status() {
    check(
        "756593622e30411517fc0000000008ffc133a8ce80000000c152030830000000414f1e10a00000003fc000000fff0057003f3431411518000000000008ff014d000000003f0000003f4000003fa00000400000000000000000000000000000000000000000f7d2df",
        None,
        &[
            "{\"offset\":0,\"set\":147,\"fields\":[{\"descriptor\":48,\"name\":\"base_station_info\",\"values\":{\"tow\":345599.0,\"week_number\":2303,\"ecef_position\":[-1288398.5,-4721696.75,4078625.25],\"height\":1.5,\"station_id\":4095,\"indicators\":87,\"valid_flags\":63}},{\"descriptor\":49,\"name\":\"rtk_corrections_status\",\"values\":{\"tow\":345600.0,\"week_number\":2303,\"epoch_status\":333,\"dongle_status\":0,\"gps_correction_latency\":0.5,\"glonass_correction_latency\":0.75,\"galileo_correction_latency\":1.25,\"beidou_correction_latency\":2.0,\"reserved\":[0,0,0,0],\"valid_flags\":247}}]}",
        ],
        false,
    );
}

/// `overview_field_descriptor_0x03` (tests/vectors/mip/sensor.yaml:9)
#[test]
fn case_overview_field_descriptor_0x03() {
    check(
        "7565800e0e033e7a63a0bb8e3b297fe5bf7f83e1",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":3,\"data\":\"3e7a63a0bb8e3b297fe5bf7f\",\"error\":\"unknown descriptor\"}]}",
        ],
        false,
    );
}

/// `overview_scaled_mag` (tests/vectors/mip/sensor.yaml:23)
#[test]
fn case_overview_scaled_mag() {
    check(
        "7565800e0e063e7a63a0bb8e3b297fe5bf7f8608",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":{\"scaled_mag\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}",
        ],
        false,
    );
}

/// `overview_gyro_mag_published` (tests/vectors/mip/sensor.yaml:33)
#[test]
fn case_overview_gyro_mag_published() {
    check(
        "7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fe0c6",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fe0c6\"}",
        ],
        true,
    );
}

/// `overview_gyro_mag` (tests/vectors/mip/sensor.yaml:46)
#[test]
fn case_overview_gyro_mag() {
    check(
        "7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fb11e",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_gyro\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}},{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":{\"scaled_mag\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}",
        ],
        false,
    );
}

/// `scaled_accel_example_gx5_published` (tests/vectors/mip/sensor.yaml:57)
#[test]
fn case_scaled_accel_example_gx5_published() {
    check(
        "7565800e0e043e7a63a0bb8e3b297fe5bf7f92c0",
        None,
        &["{\"offset\":0,\"skipped\":\"7565800e0e043e7a63a0bb8e3b297fe5bf7f92c0\"}"],
        true,
    );
}

/// `scaled_accel_example` (tests/vectors/mip/sensor.yaml:69)
#[test]
fn case_scaled_accel_example() {
    check(
        "7565800e0e043e7a63a0bb8e3b297fe5bf7f84ee",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}",
        ],
        false,
    );
}

/// `poll_imu_data_packet_published` (tests/vectors/mip/sensor.yaml:78)
#[test]
fn case_poll_imu_data_packet_published() {
    check(
        "7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7f41bb",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7f41bb\"}",
        ],
        true,
    );
}

/// `poll_imu_data_packet_as_printed` (tests/vectors/mip/sensor.yaml:91)
#[test]
fn case_poll_imu_data_packet_as_printed() {
    check(
        "7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7faddc",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}},{\"descriptor\":3,\"data\":\"3e7a63a0bb8e3b297fe5bf7f\",\"error\":\"unknown descriptor\"}]}",
        ],
        false,
    );
}

/// `poll_imu_data_packet_corrected` (tests/vectors/mip/sensor.yaml:109)
#[test]
fn case_poll_imu_data_packet_corrected() {
    check(
        "7565801c0e053e7a63a0bb8e3b297fe5bf7f0e043e7a63a0bb8e3b297fe5bf7faf04",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_gyro\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}",
        ],
        false,
    );
}

/// `accel_gyro_mag_typical` (tests/vectors/mip/sensor.yaml:122)
#[test]
fn case_accel_gyro_mag_typical() {
    check(
        "7565802a0e043f800000bf000000000000000e053e8000003a83126fc00000000e063f0000003e000000bec00000f2e2",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,0.0]}},{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_gyro\":[0.25,0.0010000000474974513,-2.0]}},{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":{\"scaled_mag\":[0.5,0.125,-0.375]}}]}",
        ],
        false,
    );
}

/// `cf_euler_poll_reply` (tests/vectors/mip/sensor.yaml:139)
#[test]
fn case_cf_euler_poll_reply() {
    check(
        "7565800e0e0cbae3ed9b3c7d6ddfbf855cf541bb",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":12,\"name\":\"cf_euler_angles\",\"values\":{\"roll\":-0.001738953753374517,\"pitch\":0.01546808984130621,\"yaw\":-1.04189932346344}}]}",
        ],
        false,
    );
}

/// `delta_theta_delta_velocity` (tests/vectors/mip/sensor.yaml:155)
#[test]
fn case_delta_theta_delta_velocity() {
    check(
        "7565801c0e073f000000be8000003e0000000e083d800000bfc0000040000000d8a2",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":7,\"name\":\"delta_theta\",\"values\":{\"delta_theta\":[0.5,-0.25,0.125]}},{\"descriptor\":8,\"name\":\"delta_velocity\",\"values\":{\"delta_velocity\":[0.0625,-1.5,2.0]}}]}",
        ],
        false,
    );
}

/// `cf_orientation_matrix_and_quaternion` (tests/vectors/mip/sensor.yaml:171)
#[test]
fn case_cf_orientation_matrix_and_quaternion() {
    check(
        "756580382609000000003f80000000000000bf800000000000000000000000000000000000003f800000120a3f0000003f000000bf0000003f00000016be",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":9,\"name\":\"cf_orientation_matrix\",\"values\":{\"m\":[0.0,1.0,0.0,-1.0,0.0,0.0,0.0,0.0,1.0]}},{\"descriptor\":10,\"name\":\"cf_quaternion\",\"values\":{\"q\":[0.5,0.5,-0.5,0.5]}}]}",
        ],
        false,
    );
}

/// `cf_euler_stabilized_north_up` (tests/vectors/mip/sensor.yaml:190)
#[test]
fn case_cf_euler_stabilized_north_up() {
    check(
        "7565802a0e0c3e800000be000000404000000e103e800000000000003f0000000e110000000000000000bf8000001344",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":12,\"name\":\"cf_euler_angles\",\"values\":{\"roll\":0.25,\"pitch\":-0.125,\"yaw\":3.0}},{\"descriptor\":16,\"name\":\"cf_stabilized_north\",\"values\":{\"stabilized_north\":[0.25,0.0,0.5]}},{\"descriptor\":17,\"name\":\"cf_stabilized_up\",\"values\":{\"stabilized_up\":[0.0,0.0,-1.0]}}]}",
        ],
        false,
    );
}

/// `imu_format_example_data_packet` (tests/vectors/mip/sensor.yaml:209)
#[test]
fn case_imu_format_example_data_packet() {
    check(
        "7565802a0e1241086a0200000000080000050e040000000000000000bf8000000e053b00000000000000bf000000c4a1",
        Some("gx5_45"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":18,\"name\":\"gps_timestamp\",\"values\":{\"tow\":200000.25,\"week_number\":2048,\"valid_flags\":5}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.0,0.0,-1.0]}},{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_gyro\":[0.001953125,0.0,-0.5]}}]}",
        ],
        false,
    );
}

/// `gps_timestamp_cv7_all_flags` (tests/vectors/mip/sensor.yaml:232)
#[test]
fn case_gps_timestamp_cv7_all_flags() {
    check(
        "7565800e0e12411a5e000000000008fc001f6478",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":18,\"name\":\"gps_timestamp\",\"values\":{\"tow\":432000.0,\"week_number\":2300,\"valid_flags\":31}}]}",
        ],
        false,
    );
}

/// `temperature_pressure_overrange_odometer` (tests/vectors/mip/sensor.yaml:246)
#[test]
fn case_temperature_pressure_overrange_odometer() {
    check(
        "756580240e1441a400004235000041f900000617447d5000041812140c40c02000003d80000000019026",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":20,\"name\":\"temperature_statistics\",\"values\":{\"min_temp\":20.5,\"max_temp\":45.25,\"mean_temp\":31.125}},{\"descriptor\":23,\"name\":\"scaled_pressure\",\"values\":{\"scaled_pressure\":1013.25}},{\"descriptor\":24,\"name\":\"overrange_status\",\"values\":{\"status\":4628}},{\"descriptor\":64,\"name\":\"odometer_data\",\"values\":{\"speed\":-2.5,\"uncertainty\":0.0625,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `event_source_reference_time_delta_theta_velocity` (tests/vectors/mip/shared.yaml:9)
#[test]
fn case_event_source_reference_time_delta_theta_velocity() {
    check(
        "7565803303d0020ad50000011f71fb04cb0ad60000000000fe502b0e073a80000000000000bf0000000e08000000003c800000bd8000009210",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":208,\"name\":\"event_source\",\"values\":{\"trigger_id\":2}},{\"descriptor\":213,\"name\":\"reference_timestamp\",\"values\":{\"nanoseconds\":1234567890123}},{\"descriptor\":214,\"name\":\"reference_time_delta\",\"values\":{\"dt_nanos\":16666667}},{\"descriptor\":7,\"name\":\"delta_theta\",\"values\":{\"delta_theta\":[0.0009765625,0.0,-0.5]}},{\"descriptor\":8,\"name\":\"delta_velocity\",\"values\":{\"delta_velocity\":[0.0,0.015625,-0.0625]}}]}",
        ],
        false,
    );
}

/// `shared_gps_timestamp_delta_time` (tests/vectors/mip/shared.yaml:33)
#[test]
fn case_shared_gps_timestamp_delta_time() {
    check(
        "756580180ed340f5180200000000092900030ad43f900000000000008423",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":211,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":3}},{\"descriptor\":212,\"name\":\"delta_time\",\"values\":{\"seconds\":0.015625}}]}",
        ],
        false,
    );
}

/// `external_time_in_system_set` (tests/vectors/mip/shared.yaml:48)
#[test]
fn case_external_time_in_system_set() {
    check(
        "7565a01f0cd717979cfe362a000000010cd800000000000f4240000104020100030305ad9f",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":160,\"fields\":[{\"descriptor\":215,\"name\":\"external_timestamp\",\"values\":{\"nanoseconds\":1700000000000000000,\"valid_flags\":1}},{\"descriptor\":216,\"name\":\"external_time_delta\",\"values\":{\"dt_nanos\":1000000,\"valid_flags\":1}},{\"descriptor\":2,\"name\":\"time_sync_status\",\"values\":{\"time_sync\":true,\"last_pps_rcvd\":0}},{\"descriptor\":3,\"name\":\"gpio_state\",\"values\":{\"states\":5}}]}",
        ],
        false,
    );
}

/// `continuation_packets_share_timestamps` (tests/vectors/mip/shared.yaml:68)
#[test]
fn case_continuation_packets_share_timestamps() {
    check(
        "756580f903d0000ed340f5180200000000092900030ad43f900000000000000ad50000011f71fb04cb0ad60000000000ee6b280cd713aef6e5f153594000010cd80000000000ee6b2800010e040000000000000000bf8000000e053b00000000000000bf0000000e063f0000003e000000bec000000e073f000000be8000003e0000000e083d800000bfc000004000000026093f8000000000000000000000000000003f8000000000000000000000000000003f800000120a3f8000000000000000000000000000000e0c3e800000be000000404000000e1240f51802000000000929001f0e1441a400004235000041f900000617447d500004180000846b7565805303d0000ed340f5180200000000092900030ad43f900000000000000ad50000011f71fb04cb0ad60000000000ee6b280cd713aef6e5f153594000010cd80000000000ee6b2800010c40c02000003d8000000001da22",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":208,\"name\":\"event_source\",\"values\":{\"trigger_id\":0}},{\"descriptor\":211,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":3}},{\"descriptor\":212,\"name\":\"delta_time\",\"values\":{\"seconds\":0.015625}},{\"descriptor\":213,\"name\":\"reference_timestamp\",\"values\":{\"nanoseconds\":1234567890123}},{\"descriptor\":214,\"name\":\"reference_time_delta\",\"values\":{\"dt_nanos\":15625000}},{\"descriptor\":215,\"name\":\"external_timestamp\",\"values\":{\"nanoseconds\":1418342400125000000,\"valid_flags\":1}},{\"descriptor\":216,\"name\":\"external_time_delta\",\"values\":{\"dt_nanos\":15625000,\"valid_flags\":1}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.0,0.0,-1.0]}},{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_gyro\":[0.001953125,0.0,-0.5]}},{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":{\"scaled_mag\":[0.5,0.125,-0.375]}},{\"descriptor\":7,\"name\":\"delta_theta\",\"values\":{\"delta_theta\":[0.5,-0.25,0.125]}},{\"descriptor\":8,\"name\":\"delta_velocity\",\"values\":{\"delta_velocity\":[0.0625,-1.5,2.0]}},{\"descriptor\":9,\"name\":\"cf_orientation_matrix\",\"values\":{\"m\":[1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0]}},{\"descriptor\":10,\"name\":\"cf_quaternion\",\"values\":{\"q\":[1.0,0.0,0.0,0.0]}},{\"descriptor\":12,\"name\":\"cf_euler_angles\",\"values\":{\"roll\":0.25,\"pitch\":-0.125,\"yaw\":3.0}},{\"descriptor\":18,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":31}},{\"descriptor\":20,\"name\":\"temperature_statistics\",\"values\":{\"min_temp\":20.5,\"max_temp\":45.25,\"mean_temp\":31.125}},{\"descriptor\":23,\"name\":\"scaled_pressure\",\"values\":{\"scaled_pressure\":1013.25}},{\"descriptor\":24,\"name\":\"overrange_status\",\"values\":{\"status\":0}}]}",
            "{\"offset\":255,\"set\":128,\"fields\":[{\"descriptor\":208,\"name\":\"event_source\",\"values\":{\"trigger_id\":0}},{\"descriptor\":211,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":3}},{\"descriptor\":212,\"name\":\"delta_time\",\"values\":{\"seconds\":0.015625}},{\"descriptor\":213,\"name\":\"reference_timestamp\",\"values\":{\"nanoseconds\":1234567890123}},{\"descriptor\":214,\"name\":\"reference_time_delta\",\"values\":{\"dt_nanos\":15625000}},{\"descriptor\":215,\"name\":\"external_timestamp\",\"values\":{\"nanoseconds\":1418342400125000000,\"valid_flags\":1}},{\"descriptor\":216,\"name\":\"external_time_delta\",\"values\":{\"dt_nanos\":15625000,\"valid_flags\":1}},{\"descriptor\":64,\"name\":\"odometer_data\",\"values\":{\"speed\":-2.5,\"uncertainty\":0.0625,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `communication_mode_write_sensor_direct` (tests/vectors/mip/system.yaml:7)
#[test]
fn case_communication_mode_write_sensor_direct() {
    check(
        "75657f040410010274bd",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":16,\"name\":\"communication_mode\",\"values\":{\"function\":1,\"mode\":2}}]}",
        ],
        false,
    );
}

/// `communication_mode_ack` (tests/vectors/mip/system.yaml:17)
#[test]
fn case_communication_mode_ack() {
    check(
        "75657f0404f11000627c",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":16,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `communication_mode_read` (tests/vectors/mip/system.yaml:26)
#[test]
fn case_communication_mode_read() {
    check(
        "75657f030310027143",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":16,\"name\":\"communication_mode\",\"values\":{\"function\":2}}]}",
        ],
        false,
    );
}

/// `communication_mode_read_placeholder` (tests/vectors/mip/system.yaml:39)
#[test]
fn case_communication_mode_read_placeholder() {
    check(
        "75657f040410020174be",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":16,\"name\":\"communication_mode\",\"values\":{\"function\":2,\"mode\":1}}]}",
        ],
        false,
    );
}

/// `communication_mode_read_reply` (tests/vectors/mip/system.yaml:52)
#[test]
fn case_communication_mode_read_reply() {
    check(
        "75657f0704f11000039001f9e4",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":16,\"ack_code\":0}},{\"descriptor\":144,\"name\":\"communication_mode_response\",\"values\":{\"mode\":1}}]}",
        ],
        false,
    );
}

/// `communication_mode_write_gnss_direct` (tests/vectors/mip/system.yaml:65)
#[test]
fn case_communication_mode_write_gnss_direct() {
    check(
        "75657f040410010375be",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":16,\"name\":\"communication_mode\",\"values\":{\"function\":1,\"mode\":3}}]}",
        ],
        false,
    );
}

/// `communication_mode_save` (tests/vectors/mip/system.yaml:75)
#[test]
fn case_communication_mode_save() {
    check(
        "75657f030310037244",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":16,\"name\":\"communication_mode\",\"values\":{\"function\":3}}]}",
        ],
        false,
    );
}

/// `communication_mode_load` (tests/vectors/mip/system.yaml:85)
#[test]
fn case_communication_mode_load() {
    check(
        "75657f030310047345",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":16,\"name\":\"communication_mode\",\"values\":{\"function\":4}}]}",
        ],
        false,
    );
}

/// `communication_mode_default` (tests/vectors/mip/system.yaml:95)
#[test]
fn case_communication_mode_default() {
    check(
        "75657f030310057446",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":16,\"name\":\"communication_mode\",\"values\":{\"function\":5}}]}",
        ],
        false,
    );
}

/// `communication_mode_nack_command_failed` (tests/vectors/mip/system.yaml:105)
#[test]
fn case_communication_mode_nack_command_failed() {
    check(
        "75657f0404f110046680",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":16,\"ack_code\":4}}]}",
        ],
        false,
    );
}

/// `streaming_built_in_test` (tests/vectors/mip/system_data.yaml:5)
#[test]
fn case_streaming_built_in_test() {
    check(
        "7565a01212012200f804422041010400000000500200b785",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":160,\"fields\":[{\"descriptor\":1,\"name\":\"built_in_test\",\"values\":{\"result\":{\"system_byte_0\":34,\"reserved_byte_1\":0,\"system_byte_2\":248,\"system_byte_3\":4,\"imu_byte_4\":66,\"imu_byte_5\":32,\"imu_byte_6\":65,\"imu_byte_7\":1,\"nav_byte_8\":4,\"reserved_byte_9\":0,\"reserved_byte_10\":0,\"reserved_byte_11\":0,\"reserved_byte_12\":0,\"gnss_byte_13\":80,\"gnss_byte_14\":2,\"reserved_byte_15\":0}}}]}",
        ],
        false,
    );
}

/// `time_sync_lost_gpio_low` (tests/vectors/mip/system_data.yaml:45)
#[test]
fn case_time_sync_lost_gpio_low() {
    check(
        "7565a007040200ff0303008c04",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":160,\"fields\":[{\"descriptor\":2,\"name\":\"time_sync_status\",\"values\":{\"time_sync\":false,\"last_pps_rcvd\":255}},{\"descriptor\":3,\"name\":\"gpio_state\",\"values\":{\"states\":0}}]}",
        ],
        false,
    );
}

/// `continuation_packets_with_garbage_and_a_reply_between` (tests/streams/mip/continuation.yaml:7)
#[test]
fn stream_continuation_packets_with_garbage_and_a_reply_between() {
    check(
        "756580f903d0000ed340f5180200000000092900030ad43f900000000000000ad50000011f71fb04cb0ad60000000000ee6b280cd713aef6e5f153594000010cd80000000000ee6b2800010e040000000000000000bf8000000e053b00000000000000bf0000000e063f0000003e000000bec000000e073f000000be8000003e0000000e083d800000bfc000004000000026093f8000000000000000000000000000003f8000000000000000000000000000003f800000120a3f8000000000000000000000000000000e0c3e800000be000000404000000e1240f51802000000000929001f0e1441a400004235000041f900000617447d500004180000846b0075007565010404f10100d56a7565805303d0000ed340f5180200000000092900030ad43f900000000000000ad50000011f71fb04cb0ad60000000000ee6b280cd713aef6e5f153594000010cd80000000000ee6b2800010c40c02000003d8000000001da22",
        Some("cv7_ins"),
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":208,\"name\":\"event_source\",\"values\":{\"trigger_id\":0}},{\"descriptor\":211,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":3}},{\"descriptor\":212,\"name\":\"delta_time\",\"values\":{\"seconds\":0.015625}},{\"descriptor\":213,\"name\":\"reference_timestamp\",\"values\":{\"nanoseconds\":1234567890123}},{\"descriptor\":214,\"name\":\"reference_time_delta\",\"values\":{\"dt_nanos\":15625000}},{\"descriptor\":215,\"name\":\"external_timestamp\",\"values\":{\"nanoseconds\":1418342400125000000,\"valid_flags\":1}},{\"descriptor\":216,\"name\":\"external_time_delta\",\"values\":{\"dt_nanos\":15625000,\"valid_flags\":1}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.0,0.0,-1.0]}},{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_gyro\":[0.001953125,0.0,-0.5]}},{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":{\"scaled_mag\":[0.5,0.125,-0.375]}},{\"descriptor\":7,\"name\":\"delta_theta\",\"values\":{\"delta_theta\":[0.5,-0.25,0.125]}},{\"descriptor\":8,\"name\":\"delta_velocity\",\"values\":{\"delta_velocity\":[0.0625,-1.5,2.0]}},{\"descriptor\":9,\"name\":\"cf_orientation_matrix\",\"values\":{\"m\":[1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0]}},{\"descriptor\":10,\"name\":\"cf_quaternion\",\"values\":{\"q\":[1.0,0.0,0.0,0.0]}},{\"descriptor\":12,\"name\":\"cf_euler_angles\",\"values\":{\"roll\":0.25,\"pitch\":-0.125,\"yaw\":3.0}},{\"descriptor\":18,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":31}},{\"descriptor\":20,\"name\":\"temperature_statistics\",\"values\":{\"min_temp\":20.5,\"max_temp\":45.25,\"mean_temp\":31.125}},{\"descriptor\":23,\"name\":\"scaled_pressure\",\"values\":{\"scaled_pressure\":1013.25}},{\"descriptor\":24,\"name\":\"overrange_status\",\"values\":{\"status\":0}}]}",
            "{\"offset\":255,\"skipped\":\"007500\"}",
            "{\"offset\":258,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
            "{\"offset\":268,\"set\":128,\"fields\":[{\"descriptor\":208,\"name\":\"event_source\",\"values\":{\"trigger_id\":0}},{\"descriptor\":211,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":3}},{\"descriptor\":212,\"name\":\"delta_time\",\"values\":{\"seconds\":0.015625}},{\"descriptor\":213,\"name\":\"reference_timestamp\",\"values\":{\"nanoseconds\":1234567890123}},{\"descriptor\":214,\"name\":\"reference_time_delta\",\"values\":{\"dt_nanos\":15625000}},{\"descriptor\":215,\"name\":\"external_timestamp\",\"values\":{\"nanoseconds\":1418342400125000000,\"valid_flags\":1}},{\"descriptor\":216,\"name\":\"external_time_delta\",\"values\":{\"dt_nanos\":15625000,\"valid_flags\":1}},{\"descriptor\":64,\"name\":\"odometer_data\",\"values\":{\"speed\":-2.5,\"uncertainty\":0.0625,\"valid_flags\":1}}]}",
        ],
        false,
    );
}

/// `zero_length_fields` (tests/streams/mip/fields.yaml:7)
#[test]
fn stream_zero_length_fields() {
    check(
        "75658012020402fe0e043f800000bf00000040000000427b",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"data\":\"\",\"error\":\"scaled_accel[0]: needs 4 bytes at offset 0, 0 left\"},{\"descriptor\":254,\"data\":\"\",\"error\":\"unknown descriptor\"},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}}]}",
        ],
        false,
    );
}

/// `field_length_zero_after_a_field` (tests/streams/mip/fields.yaml:21)
#[test]
fn stream_field_length_zero_after_a_field() {
    check(
        "756580120e043f800000bf000000400000000004112273a1",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"trailing\":\"00041122\",\"error\":\"field length 0 at payload offset 14 is shorter than the field header\"}]}",
        ],
        false,
    );
}

/// `short_field_does_not_stop_the_next` (tests/streams/mip/fields.yaml:33)
#[test]
fn stream_short_field_does_not_stop_the_next() {
    check(
        "756580180a043f800000bf0000000e053e80000000000000c0400000cf9c",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"data\":\"3f800000bf000000\",\"error\":\"scaled_accel[2]: needs 4 bytes at offset 8, 0 left\"},{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_gyro\":[0.25,0.0,-3.0]}}]}",
        ],
        false,
    );
}

/// `invalid_bool_byte` (tests/streams/mip/fields.yaml:46)
#[test]
fn stream_invalid_bool_byte() {
    check(
        "75650c03039e028c20",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":158,\"data\":\"02\",\"error\":\"enable: invalid bool value 2 at offset 0\"}]}",
        ],
        false,
    );
}

/// `count_past_the_maximum` (tests/streams/mip/fields.yaml:56)
#[test]
fn stream_count_past_the_maximum() {
    check(
        "75650e0303810877f6",
        None,
        &[
            "{\"offset\":0,\"set\":14,\"fields\":[{\"descriptor\":129,\"data\":\"08\",\"error\":\"receiver_info: count 8 exceeds maximum 7\"}]}",
        ],
        false,
    );
}

/// `unknown_enum_value_is_kept` (tests/streams/mip/fields.yaml:66)
#[test]
fn stream_unknown_enum_value_is_kept() {
    check(
        "75650d0505d0007f014116",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":208,\"name\":\"aiding_measurement_control_response\",\"values\":{\"source\":127,\"enable\":true}}]}",
        ],
        false,
    );
}

/// `reserved_bits_are_kept` (tests/streams/mip/fields.yaml:77)
#[test]
fn stream_reserved_bits_are_kept() {
    check(
        "7565800e0ed340f51802000000000929ffffc861",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":211,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":65535}}]}",
        ],
        false,
    );
}

/// `shared_descriptor_in_an_undefined_data_set` (tests/streams/mip/fields.yaml:88)
#[test]
fn stream_shared_descriptor_in_an_undefined_data_set() {
    check(
        "7565a70e0ed340f518020000000009290003f4d7",
        None,
        &[
            "{\"offset\":0,\"set\":167,\"fields\":[{\"descriptor\":211,\"name\":\"gps_timestamp\",\"values\":{\"tow\":86400.125,\"week_number\":2345,\"valid_flags\":3}}]}",
        ],
        false,
    );
}

/// `set_zero_has_no_kind` (tests/streams/mip/fields.yaml:99)
#[test]
fn stream_set_zero_has_no_kind() {
    check(
        "756500020201dfc2",
        None,
        &[
            "{\"offset\":0,\"set\":0,\"fields\":[{\"descriptor\":1,\"data\":\"\",\"error\":\"unknown descriptor set\"}]}",
        ],
        false,
    );
}

/// `ack_descriptor_in_a_data_set` (tests/streams/mip/fields.yaml:109)
#[test]
fn stream_ack_descriptor_in_a_data_set() {
    check(
        "7565800404f101005464",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":241,\"data\":\"0100\",\"error\":\"unknown descriptor\"}]}",
        ],
        false,
    );
}

/// `empty_stream` (tests/streams/mip/framing.yaml:9)
#[test]
fn stream_empty_stream() {
    check("", None, &[], false);
}

/// `only_garbage` (tests/streams/mip/framing.yaml:13)
#[test]
fn stream_only_garbage() {
    check(
        "000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f\"}",
        ],
        true,
    );
}

/// `garbage_inside_packet` (tests/streams/mip/framing.yaml:20)
#[test]
fn stream_garbage_inside_packet() {
    check(
        "75650102aabbcc0201e0c6756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"75650102aabbcc0201e0c6\"}",
            "{\"offset\":11,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `sync_bytes_inside_a_valid_payload` (tests/streams/mip/framing.yaml:36)
#[test]
fn stream_sync_bytes_inside_a_valid_payload() {
    check(
        "7565800606fe7565756518b5756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":254,\"data\":\"75657565\",\"error\":\"unknown descriptor\"}]}",
            "{\"offset\":12,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `lone_sync_bytes_between_packets` (tests/streams/mip/framing.yaml:52)
#[test]
fn stream_lone_sync_bytes_between_packets() {
    check(
        "756501020201e0c675756501020201e0c665756501020201e0c6756501",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":8,\"skipped\":\"75\"}",
            "{\"offset\":9,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":17,\"skipped\":\"65\"}",
            "{\"offset\":18,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":26,\"skipped\":\"756501\"}",
        ],
        false,
    );
}

/// `repeated_sync_pairs_before_a_packet` (tests/streams/mip/framing.yaml:77)
#[test]
fn stream_repeated_sync_pairs_before_a_packet() {
    check(
        "756575657565756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"756575657565\"}",
            "{\"offset\":6,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `false_sync_of_maximum_length_over_two_packets` (tests/streams/mip/framing.yaml:91)
#[test]
fn stream_false_sync_of_maximum_length_over_two_packets() {
    check(
        "756580ff756501020201e0c67565010404f10100d56a",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"756580ff\"}",
            "{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":12,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `checksum_bytes_swapped` (tests/streams/mip/framing.yaml:109)
#[test]
fn stream_checksum_bytes_swapped() {
    check(
        "756501020201c6e0756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"756501020201c6e0\"}",
            "{\"offset\":8,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `longest_legal_packet` (tests/streams/mip/framing.yaml:122)
#[test]
fn stream_longest_legal_packet() {
    check(
        "756580ff0e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf000000400000000e043f800000bf0000004000000003fe00faf6756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[1.0,-0.5,2.0]}},{\"descriptor\":254,\"data\":\"00\",\"error\":\"unknown descriptor\"}]}",
            "{\"offset\":261,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `empty_payloads` (tests/streams/mip/framing.yaml:167)
#[test]
fn stream_empty_payloads() {
    check(
        "756580005a0375650100db05",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[]}",
            "{\"offset\":6,\"set\":1,\"fields\":[]}",
        ],
        false,
    );
}

/// `truncated_packet_after_a_valid_one` (tests/streams/mip/framing.yaml:176)
#[test]
fn stream_truncated_packet_after_a_valid_one() {
    check(
        "756501020201e0c6756501020201e0",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":8,\"skipped\":\"756501020201e0\"}",
        ],
        false,
    );
}

/// `mscip_packet_in_a_mip_stream` (tests/streams/mip/framing.yaml:190)
#[test]
fn stream_mscip_packet_in_a_mip_stream() {
    check(
        "756501020201e0c6a5a5010202004f25756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":8,\"skipped\":\"a5a5010202004f25\"}",
            "{\"offset\":16,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `garbage_around_ping` (tests/streams/mip/framing_and_fields.yaml:5)
#[test]
fn stream_garbage_around_ping() {
    check(
        "00ff756501020201e0c675",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"00ff\"}",
            "{\"offset\":2,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":10,\"skipped\":\"75\"}",
        ],
        false,
    );
}

/// `false_sync_running_past_the_end` (tests/streams/mip/framing_and_fields.yaml:19)
#[test]
fn stream_false_sync_running_past_the_end() {
    check(
        "75650110756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"75650110\"}",
            "{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `bad_checksum_then_valid` (tests/streams/mip/framing_and_fields.yaml:32)
#[test]
fn stream_bad_checksum_then_valid() {
    check(
        "756501020201e0c77565010404f10100d56a",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"756501020201e0c7\"}",
            "{\"offset\":8,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `packet_inside_false_packet` (tests/streams/mip/framing_and_fields.yaml:45)
#[test]
fn stream_packet_inside_false_packet() {
    check(
        "7565010a756501020201e0c600000000",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"7565010a\"}",
            "{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":12,\"skipped\":\"00000000\"}",
        ],
        false,
    );
}

/// `truncated_packet_at_end` (tests/streams/mip/framing_and_fields.yaml:61)
#[test]
fn stream_truncated_packet_at_end() {
    check(
        "7565010404f1",
        None,
        &["{\"offset\":0,\"skipped\":\"7565010404f1\"}"],
        true,
    );
}

/// `field_length_overruns_payload` (tests/streams/mip/framing_and_fields.yaml:66)
#[test]
fn stream_field_length_overruns_payload() {
    check(
        "7565010402010302e798",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}},{\"trailing\":\"0302\",\"error\":\"field length 3 at payload offset 2 overruns the payload (2 bytes left)\"}]}",
        ],
        false,
    );
}

/// `field_length_below_header` (tests/streams/mip/framing_and_fields.yaml:78)
#[test]
fn stream_field_length_below_header() {
    check(
        "756501020101dfc4",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"trailing\":\"0101\",\"error\":\"field length 1 at payload offset 0 is shorter than the field header\"}]}",
        ],
        false,
    );
}

/// `field_too_short_for_type` (tests/streams/mip/framing_and_fields.yaml:88)
#[test]
fn stream_field_too_short_for_type() {
    check(
        "7565800a0a043f800000bf000000f0f1",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"data\":\"3f800000bf000000\",\"error\":\"scaled_accel[2]: needs 4 bytes at offset 8, 0 left\"}]}",
        ],
        false,
    );
}

/// `field_with_trailing_bytes` (tests/streams/mip/framing_and_fields.yaml:99)
#[test]
fn stream_field_with_trailing_bytes() {
    check(
        "756501030302553804",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"data\":\"55\",\"error\":\"1 unexpected bytes at offset 0\"}]}",
        ],
        false,
    );
}

/// `unknown_set_and_descriptor` (tests/streams/mip/framing_and_fields.yaml:109)
#[test]
fn stream_unknown_set_and_descriptor() {
    check(
        "7565a70404331234026a",
        None,
        &[
            "{\"offset\":0,\"set\":167,\"fields\":[{\"descriptor\":51,\"data\":\"1234\",\"error\":\"unknown descriptor set\"}]}",
        ],
        false,
    );
}

/// `ack_in_undefined_command_set` (tests/streams/mip/framing_and_fields.yaml:119)
#[test]
fn stream_ack_in_undefined_command_set() {
    check(
        "75657e0404f110006176",
        None,
        &[
            "{\"offset\":0,\"set\":126,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":16,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `union_selector_without_member` (tests/streams/mip/framing_and_fields.yaml:130)
#[test]
fn stream_union_selector_without_member() {
    check(
        "75650c07072e0101090104320c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"data\":\"0101090104\",\"error\":\"parameters: no member for selector value 9\"}]}",
        ],
        false,
    );
}

/// `rtcm_bad_crc_over_a_packet` (tests/streams/mip/mixed_nmea_rtcm.yaml:74)
#[test]
fn stream_rtcm_bad_crc_over_a_packet() {
    check(
        "d3000c3ed0756501020201e0c6aabb321af0756501020201e0c6",
        None,
        &[
            "{\"offset\":0,\"skipped\":\"d3000c3ed0\"}",
            "{\"offset\":5,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":13,\"skipped\":\"aabb321af0\"}",
            "{\"offset\":18,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
        ],
        false,
    );
}

/// `rtcm_cut_short_at_the_end` (tests/streams/mip/mixed_nmea_rtcm.yaml:95)
#[test]
fn stream_rtcm_cut_short_at_the_end() {
    check(
        "756501020201e0c6d300133ed7d30202980edeef34b4bd62ac094198",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
            "{\"offset\":8,\"skipped\":\"d300133ed7d30202980edeef34b4bd62ac094198\"}",
        ],
        false,
    );
}
