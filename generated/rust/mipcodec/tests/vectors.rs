//! Golden vectors (tests/vectors/mip/): each case's bytes decode (whole, and fed one
//! byte at a time) to exactly the expected canonical JSON lines, and those lines encode back to
//! the bytes.

use mipcodec::text::{decode_bytes, encode_text};
use mipcodec::Device;

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
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":8,\"ack_code\":0}},{\"descriptor\":136,\"name\":\"continuous_bit_result\",\"values\":{\"result\":[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15]}}]}",
        ],
        false,
    );
}

/// `comm_port_speed_write` (tests/vectors/mip/base.yaml:269)
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

/// `comm_port_speed_read` (tests/vectors/mip/base.yaml:281)
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

/// `comm_port_speed_save_all` (tests/vectors/mip/base.yaml:292)
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

/// `comm_port_speed_read_reply` (tests/vectors/mip/base.yaml:302)
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

/// `gps_time_update_write_week` (tests/vectors/mip/base.yaml:315)
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

/// `gps_time_update_table_published` (tests/vectors/mip/base.yaml:324)
#[test]
fn case_gps_time_update_table_published() {
    check(
        "756501080872010000000698fd32",
        None,
        &["{\"offset\":0,\"skipped\":\"756501080872010000000698fd32\"}"],
        true,
    );
}

/// `gps_time_update_reply` (tests/vectors/mip/base.yaml:337)
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

/// `gps_time_update_read_week` (tests/vectors/mip/base.yaml:346)
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

/// `gps_week_reply` (tests/vectors/mip/base.yaml:358)
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

/// `gps_seconds_reply` (tests/vectors/mip/base.yaml:371)
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

/// `gps_time_update_write_no_ack` (tests/vectors/mip/base.yaml:384)
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

/// `device_reset_command` (tests/vectors/mip/base.yaml:396)
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

/// `device_reset_reply` (tests/vectors/mip/base.yaml:405)
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

/// `nack_invalid_parameter` (tests/vectors/mip/base.yaml:414)
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

/// `two_commands_one_packet` (tests/vectors/mip/base.yaml:425)
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

/// `gps_time_update_write_week_cv7` (tests/vectors/mip/base.yaml:438)
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

/// `built_in_test_reply_cv7_flags` (tests/vectors/mip/base.yaml:452)
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

/// `device_info_every_string_byte` (tests/vectors/mip/base.yaml:466)
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

/// `ack_imu_message_format` (tests/vectors/mip/base.yaml:493)
#[test]
fn case_ack_imu_message_format() {
    check(
        "75650c0404f10800e7ba",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":8,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `ack_filter_message_format` (tests/vectors/mip/base.yaml:501)
#[test]
fn case_ack_filter_message_format() {
    check(
        "75650c0404f10a00e9be",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":10,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `two_acks_save_formats_published` (tests/vectors/mip/base.yaml:509)
#[test]
fn case_two_acks_save_formats_published() {
    check(
        "75650c0804f1080004f10a00e9be",
        None,
        &["{\"offset\":0,\"skipped\":\"75650c0804f1080004f10a00e9be\"}"],
        true,
    );
}

/// `two_acks_save_formats` (tests/vectors/mip/base.yaml:521)
#[test]
fn case_two_acks_save_formats() {
    check(
        "75650c0804f1080004f10a00ea71",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":8,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":10,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `two_acks_enable_streams` (tests/vectors/mip/base.yaml:533)
#[test]
fn case_two_acks_enable_streams() {
    check(
        "75650c0804f1110004f11100fab5",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":17,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `ack_poll_data` (tests/vectors/mip/base.yaml:542)
#[test]
fn case_ack_poll_data() {
    check(
        "75650c0404f10100e0ac",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `ack_initialize_attitude` (tests/vectors/mip/base.yaml:552)
#[test]
fn case_ack_initialize_attitude() {
    check(
        "75650d0404f10200e2b4",
        None,
        &[
            "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":2,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `ack_pps_source` (tests/vectors/mip/base.yaml:560)
#[test]
fn case_ack_pps_source() {
    check(
        "75650c0404f1280007fa",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":40,\"ack_code\":0}}]}",
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

/// `event_trigger_threshold_roll_10` (tests/vectors/mip/events.yaml:251)
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

/// `event_trigger_combination_latch` (tests/vectors/mip/events.yaml:267)
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

/// `event_action_gpio_oneshot_low` (tests/vectors/mip/events.yaml:277)
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

/// `event_trigger_config_read` (tests/vectors/mip/events.yaml:287)
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

/// `event_trigger_config_read_reply_none` (tests/vectors/mip/events.yaml:298)
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

/// `get_event_action_status_all_reply` (tests/vectors/mip/events.yaml:311)
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

/// `doubles_power_of_two_and_negative_zero` (tests/vectors/mip/events.yaml:329)
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

/// `doubles_denormal_and_1e16` (tests/vectors/mip/events.yaml:343)
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

/// `doubles_positional_boundary` (tests/vectors/mip/events.yaml:354)
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

/// `doubles_large_values` (tests/vectors/mip/events.yaml:365)
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

/// `doubles_infinity_and_nan_payload` (tests/vectors/mip/events.yaml:376)
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

/// `garbage_around_ping` (tests/vectors/mip/streams.yaml:5)
#[test]
fn case_garbage_around_ping() {
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

/// `false_sync_running_past_the_end` (tests/vectors/mip/streams.yaml:19)
#[test]
fn case_false_sync_running_past_the_end() {
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

/// `bad_checksum_then_valid` (tests/vectors/mip/streams.yaml:32)
#[test]
fn case_bad_checksum_then_valid() {
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

/// `packet_inside_false_packet` (tests/vectors/mip/streams.yaml:45)
#[test]
fn case_packet_inside_false_packet() {
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

/// `truncated_packet_at_end` (tests/vectors/mip/streams.yaml:61)
#[test]
fn case_truncated_packet_at_end() {
    check(
        "7565010404f1",
        None,
        &["{\"offset\":0,\"skipped\":\"7565010404f1\"}"],
        true,
    );
}

/// `field_length_overruns_payload` (tests/vectors/mip/streams.yaml:66)
#[test]
fn case_field_length_overruns_payload() {
    check(
        "7565010402010302e798",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}},{\"trailing\":\"0302\",\"error\":\"field length 3 at payload offset 2 overruns the payload (2 bytes left)\"}]}",
        ],
        false,
    );
}

/// `field_length_below_header` (tests/vectors/mip/streams.yaml:78)
#[test]
fn case_field_length_below_header() {
    check(
        "756501020101dfc4",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"trailing\":\"0101\",\"error\":\"field length 1 at payload offset 0 is shorter than the field header\"}]}",
        ],
        false,
    );
}

/// `field_too_short_for_type` (tests/vectors/mip/streams.yaml:88)
#[test]
fn case_field_too_short_for_type() {
    check(
        "7565800a0a043f800000bf000000f0f1",
        None,
        &[
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"data\":\"3f800000bf000000\",\"error\":\"scaled_accel[2]: needs 4 bytes at offset 8, 0 left\"}]}",
        ],
        false,
    );
}

/// `field_with_trailing_bytes` (tests/vectors/mip/streams.yaml:99)
#[test]
fn case_field_with_trailing_bytes() {
    check(
        "756501030302553804",
        None,
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"data\":\"55\",\"error\":\"1 unexpected bytes at offset 0\"}]}",
        ],
        false,
    );
}

/// `unknown_set_and_descriptor` (tests/vectors/mip/streams.yaml:109)
#[test]
fn case_unknown_set_and_descriptor() {
    check(
        "7565a70404331234026a",
        None,
        &[
            "{\"offset\":0,\"set\":167,\"fields\":[{\"descriptor\":51,\"data\":\"1234\",\"error\":\"unknown descriptor set\"}]}",
        ],
        false,
    );
}

/// `ack_in_undefined_command_set` (tests/vectors/mip/streams.yaml:119)
#[test]
fn case_ack_in_undefined_command_set() {
    check(
        "75657f0404f11000627c",
        None,
        &[
            "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":16,\"ack_code\":0}}]}",
        ],
        false,
    );
}

/// `union_selector_without_member` (tests/vectors/mip/streams.yaml:130)
#[test]
fn case_union_selector_without_member() {
    check(
        "75650c07072e0101090104320c",
        None,
        &[
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"data\":\"0101090104\",\"error\":\"parameters: no member for selector value 9\"}]}",
        ],
        false,
    );
}
