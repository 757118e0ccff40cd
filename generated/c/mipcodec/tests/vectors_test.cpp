// Golden vectors (tests/vectors/): decode the bytes (whole and byte by byte) and compare the
// exact JSON lines; encode the lines back and compare the bytes. Generated: do not edit.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace {

[[maybe_unused]] void check_vector(const char *hex, mip_device_t device, const char *expect) {
    using namespace test_support;
    std::vector<uint8_t> bytes = from_hex(hex);
    EXPECT_EQ(decode_text(bytes, 0, device), expect) << "decoded whole";
    EXPECT_EQ(decode_text(bytes, 1, device), expect) << "decoded one byte at a time";
    std::vector<uint8_t> encoded;
    std::string error;
    ASSERT_TRUE(encode_text(expect, &encoded, &error)) << error;
    EXPECT_EQ(to_hex(encoded), hex) << "encoded from the expected lines";
}

} // namespace

TEST(Vectors, ping_command) {
    check_vector(
        "756501020201e0c6", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Vectors, ping_reply) {
    check_vector("7565010404f10100d56a", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":1,\"ack_code\":0}}]}\n");
}

TEST(Vectors, set_to_idle_command) {
    check_vector(
        "756501020202e1c7", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]}\n");
}

TEST(Vectors, set_to_idle_copy_paste_published) {
    check_vector(
        "756501020201e0c6", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Vectors, set_to_idle_reply) {
    check_vector("7565010404f10200d66c", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":2,\"ack_code\":0}}]}\n");
}

TEST(Vectors, get_device_info_command) {
    check_vector("756501020203e2c8", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"get_device_info\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, get_device_info_reply) {
    check_vector(
        "7565015804f10300548105fe33444d2d4758352d3435202020202020363233322d3432373020202020202020363233322d30"
        "303132322020202020202020202020202020202020202020202035672c20313530642f73202020202020b801",
        MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_"
        "descriptor\":3,\"ack_code\":0}},{\"descriptor\":129,\"name\":\"device_info\",\"values\":{\"info\":{"
        "\"firmware_version\":1534,\"model_name\":\"3DM-GX5-45      \",\"model_number\":\"6232-4270       "
        "\",\"serial_number\":\"6232-00122      \",\"lot_number\":\"                "
        "\",\"device_options\":\"5g, 150d/s      \"}}}]}\n");
}

TEST(Vectors, get_device_descriptors_command) {
    check_vector("756501020204e3c9", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"get_device_descriptors\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, get_device_descriptors_reply) {
    check_vector("7565011204f104000e820101010201030c010c020c721805", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":4,\"ack_code\":0}},{\"descriptor\":130,\"name\":\"device_"
                 "descriptors\",\"values\":{\"descriptors\":[257,258,259,3073,3074,3186]}}]}\n");
}

TEST(Vectors, get_device_descriptors_reply_empty) {
    check_vector("7565010604f1040002825eb4", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":4,\"ack_code\":0}},{\"descriptor\":130,\"name\":\"device_"
                 "descriptors\",\"values\":{\"descriptors\":[]}}]}\n");
}

TEST(Vectors, built_in_test_command) {
    check_vector("756501020205e4ca", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"built_in_test\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, built_in_test_reply) {
    check_vector("7565010a04f10500068300000000687d", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":5,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"built_in_test_"
                 "result\",\"device\":\"gx5_45\",\"values\":{\"flags\":0}}]}\n");
}

TEST(Vectors, built_in_test_reply_gx5_flags) {
    check_vector("7565010a04f105000683010003016d88", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":5,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"built_in_test_"
                 "result\",\"device\":\"gx5_45\",\"values\":{\"flags\":16777985}}]}\n");
}

TEST(Vectors, resume_command) {
    check_vector(
        "756501020206e5cb", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":6,\"name\":\"resume\",\"values\":{}}]}\n");
}

TEST(Vectors, resume_reply) {
    check_vector("7565010404f10600da74", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":6,\"ack_code\":0}}]}\n");
}

TEST(Vectors, resume_reply_table_published) {
    check_vector("7565010404f10100da74", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"7565010404f10100da74\"}\n");
}

TEST(Vectors, get_extended_descriptors_command) {
    check_vector("756501020207e6cc", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":7,\"name\":\"get_extended_"
                 "descriptors\",\"values\":{}}]}\n");
}

TEST(Vectors, get_extended_descriptors_table_published) {
    check_vector("756501020204e6cc", MIP_DEVICE_ANY, "{\"offset\":0,\"skipped\":\"756501020204e6cc\"}\n");
}

TEST(Vectors, get_extended_descriptors_reply) {
    check_vector("7565010e04f107000a860d270d28822b822c39fc", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":7,\"ack_code\":0}},{\"descriptor\":134,\"name\":\"extended_"
                 "descriptors\",\"values\":{\"descriptors\":[3367,3368,33323,33324]}}]}\n");
}

TEST(Vectors, continuous_bit_command) {
    check_vector("756501020208e7cd", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":8,\"name\":\"continuous_bit\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, continuous_bit_reply) {
    check_vector("7565011604f108001288000102030405060708090a0b0c0d0e0f0082", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":8,\"ack_code\":0}},{\"descriptor\":136,\"name\":\"continuous_bit_"
                 "result\",\"values\":{\"result\":[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15]}}]}\n");
}

TEST(Vectors, comm_port_speed_write) {
    check_vector("75650108080901010001c200b936", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"comm_port_speed\","
                 "\"values\":{\"function\":1,\"port\":1,\"baud\":115200}}]}\n");
}

TEST(Vectors, comm_port_speed_read) {
    check_vector("7565010404090201efb5", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"comm_port_speed\","
                 "\"values\":{\"function\":2,\"port\":1}}]}\n");
}

TEST(Vectors, comm_port_speed_save_all) {
    check_vector("7565010404090300efb6", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"comm_port_speed\","
                 "\"values\":{\"function\":3,\"port\":0}}]}\n");
}

TEST(Vectors, comm_port_speed_read_reply) {
    check_vector("7565010b04f10900078901000e1000938f", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":9,\"ack_code\":0}},{\"descriptor\":137,\"name\":\"comm_port_speed_"
                 "response\",\"values\":{\"port\":1,\"baud\":921600}}]}\n");
}

TEST(Vectors, gps_time_update_write_week) {
    check_vector("756501080872010100000698fd32", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\","
                 "\"device\":\"gx5_45\",\"values\":{\"function\":1,\"field_id\":1,\"value\":1688}}]}\n");
}

TEST(Vectors, gps_time_update_table_published) {
    check_vector("756501080872010000000698fd32", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"756501080872010000000698fd32\"}\n");
}

TEST(Vectors, gps_time_update_reply) {
    check_vector("7565010404f17200464c", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":114,\"ack_code\":0}}]}\n");
}

TEST(Vectors, gps_time_update_read_week) {
    check_vector("756501040472020158f0", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\","
                 "\"device\":\"gx5_45\",\"values\":{\"function\":2,\"field_id\":1}}]}\n");
}

TEST(Vectors, gps_week_reply) {
    check_vector("7565010a04f17200068400000698748e", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":114,\"ack_code\":0}},{\"descriptor\":132,\"name\":\"gps_week\","
                 "\"values\":{\"week\":1688}}]}\n");
}

TEST(Vectors, gps_seconds_reply) {
    check_vector("7565010a04f17200068500054600228a", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":114,\"ack_code\":0}},{\"descriptor\":133,\"name\":\"gps_seconds\","
                 "\"values\":{\"seconds\":345600}}]}\n");
}

TEST(Vectors, gps_time_update_write_no_ack) {
    check_vector("756501080872060200054600b04c", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\","
                 "\"device\":\"gx5_45\",\"values\":{\"function\":6,\"field_id\":2,\"value\":345600}}]}\n");
}

TEST(Vectors, device_reset_command) {
    check_vector("75650102027e5d43", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":126,\"name\":\"device_reset\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, device_reset_reply) {
    check_vector("7565010404f17e005264", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":126,\"ack_code\":0}}]}\n");
}

TEST(Vectors, nack_invalid_parameter) {
    check_vector("7565010404f17e035567", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":126,\"ack_code\":3}}]}\n");
}

TEST(Vectors, two_commands_one_packet) {
    check_vector("7565010402010202e696", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}},{"
                 "\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]}\n");
}

TEST(Vectors, gps_time_update_write_week_cv7) {
    check_vector("756501080872010100000698fd32", MIP_DEVICE_CV7_INS,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":114,\"name\":\"gps_time_update\","
                 "\"device\":\"cv7_ins\",\"values\":{\"function\":1,\"field_id\":1,\"value\":1688}}]}\n");
}

TEST(Vectors, built_in_test_reply_cv7_flags) {
    check_vector("7565010a04f10500068300802000083d", MIP_DEVICE_CV7_INS,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":5,\"ack_code\":0}},{\"descriptor\":131,\"name\":\"built_in_test_"
                 "result\",\"device\":\"cv7_ins\",\"values\":{\"flags\":8396800}}]}\n");
}

TEST(Vectors, device_info_every_string_byte) {
    check_vector("756501545481ffff5122425c00011f7f80ff7e20090a0d5a0000000000000000000000000000000020202020202"
                 "020202020202020202020202122232425262728292a2b2c2d2e2ff0f1f2f3f4f5f6f7f8f9fafbfcfdfeff39e6",
                 MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":129,\"name\":\"device_info\","
                 "\"values\":{\"info\":{\"firmware_version\":65535,\"model_name\":"
                 "\"Q\\\"B\\\\\\u0000\\u0001\\u001f\\u007f\\u0080\\u00ff~ "
                 "\\u0009\\u000a\\u000dZ\",\"model_number\":"
                 "\"\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u00"
                 "00\\u0000\\u0000\\u0000\",\"serial_number\":\"                \",\"lot_number\":\" "
                 "!\\\"#$%&'()*+,-./"
                 "\",\"device_options\":"
                 "\"\\u00f0\\u00f1\\u00f2\\u00f3\\u00f4\\u00f5\\u00f6\\u00f7\\u00f8\\u00f9\\u00fa\\u00fb\\u00"
                 "fc\\u00fd\\u00fe\\u00ff\"}}}]}\n");
}

TEST(Vectors, ack_imu_message_format) {
    check_vector("75650c0404f10800e7ba", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":8,\"ack_code\":0}}]}\n");
}

TEST(Vectors, ack_filter_message_format) {
    check_vector("75650c0404f10a00e9be", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":10,\"ack_code\":0}}]}\n");
}

TEST(Vectors, two_acks_save_formats_published) {
    check_vector("75650c0804f1080004f10a00e9be", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"75650c0804f1080004f10a00e9be\"}\n");
}

TEST(Vectors, two_acks_save_formats) {
    check_vector("75650c0804f1080004f10a00ea71", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":8,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\","
                 "\"values\":{\"command_descriptor\":10,\"ack_code\":0}}]}\n");
}

TEST(Vectors, two_acks_enable_streams) {
    check_vector("75650c0804f1110004f11100fab5", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":17,\"ack_code\":0}},{\"descriptor\":241,\"name\":\"ack_nack\","
                 "\"values\":{\"command_descriptor\":17,\"ack_code\":0}}]}\n");
}

TEST(Vectors, ack_poll_data) {
    check_vector("75650c0404f10100e0ac", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":1,\"ack_code\":0}}]}\n");
}

TEST(Vectors, ack_initialize_attitude) {
    check_vector("75650d0404f10200e2b4", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":13,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":2,\"ack_code\":0}}]}\n");
}

TEST(Vectors, ack_pps_source) {
    check_vector("75650c0404f1280007fa", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":40,\"ack_code\":0}}]}\n");
}

TEST(Vectors, event_trigger_gpio_edge) {
    check_vector(
        "75650c07072e01010101042af4", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":1,\"type\":1,\"parameters\":{\"pin\":1,\"mode\":4}}}]}\n");
}

TEST(Vectors, event_action_message_sensor) {
    check_vector("75650c0f0f2f0101010280000005d0d5d6070847ca", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_"
                 "set\":128,\"decimation\":0,\"num_fields\":5,\"descriptors\":[208,213,214,7,8]}}}]}\n");
}

TEST(Vectors, event_action_message_filter) {
    check_vector("75650c0e0e2f0102010282000004d0d5d6053d7a", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":2,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_"
                 "set\":130,\"decimation\":0,\"num_fields\":4,\"descriptors\":[208,213,214,5]}}}]}\n");
}

TEST(Vectors, event_control_enable_1) {
    check_vector("75650c05052b0101011e82", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":43,\"name\":\"event_control\","
                 "\"values\":{\"function\":1,\"instance\":1,\"mode\":1}}]}\n");
}

TEST(Vectors, event_action_gpio_active_high) {
    check_vector("75650c08082f0101010101012b31", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":1,\"parameters\":{\"pin\":"
                 "1,\"mode\":1}}}]}\n");
}

TEST(Vectors, event_trigger_threshold_interval) {
    check_vector(
        "75650c19192e01010280d50102415fca0540000000416fca0560000000308a", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":1,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_"
        "desc\":213,\"param_id\":1,\"type\":2,\"low_thres\":8333333.0,\"high_thres\":16666667.0}}}]}\n");
}

TEST(Vectors, event_trigger_gpio_while_low) {
    check_vector(
        "75650c07072e01010103022af6", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":1,\"type\":1,\"parameters\":{\"pin\":3,\"mode\":2}}}]}\n");
}

TEST(Vectors, get_event_trigger_status_1) {
    check_vector("75650c04042c01011c5e", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":44,\"name\":\"get_event_trigger_"
                 "status\",\"values\":{\"requested_count\":1,\"requested_instances\":[1]}}]}\n");
}

TEST(Vectors, event_trigger_status_enabled) {
    check_vector("75650c0904f12c0005b6010102cf63", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":44,\"ack_code\":0}},{\"descriptor\":182,\"name\":\"event_trigger_"
                 "status\",\"values\":{\"count\":1,\"triggers\":[{\"type\":1,\"status\":2}]}}]}\n");
}

TEST(Vectors, event_trigger_status_active) {
    check_vector("75650c0904f12c0005b6010103d064", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":44,\"ack_code\":0}},{\"descriptor\":182,\"name\":\"event_trigger_"
                 "status\",\"values\":{\"count\":1,\"triggers\":[{\"type\":1,\"status\":3}]}}]}\n");
}

TEST(Vectors, event_action_message_decimated_sensor) {
    check_vector("75650c0c0c2f0101010280000a020405c778", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_"
                 "set\":128,\"decimation\":10,\"num_fields\":2,\"descriptors\":[4,5]}}}]}\n");
}

TEST(Vectors, event_action_message_decimated_filter) {
    check_vector("75650c0b0b2f0102010282000a0105c3ab", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":2,\"trigger\":1,\"type\":2,\"parameters\":{\"desc_"
                 "set\":130,\"decimation\":10,\"num_fields\":1,\"descriptors\":[5]}}}]}\n");
}

TEST(Vectors, event_action_gpio_oneshot_high) {
    check_vector("75650c08082f010101010405323b", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":1,\"trigger\":1,\"type\":1,\"parameters\":{\"pin\":"
                 "4,\"mode\":5}}}]}\n");
}

TEST(Vectors, event_trigger_threshold_roll_45) {
    check_vector(
        "75650c19192e010102800c01013fe921fb323ae5afbfe921fb323ae5afe040", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":1,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_"
        "desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":0.7853981,\"high_thres\":-0.7853981}}}]}\n");
}

TEST(Vectors, event_trigger_threshold_pitch_45) {
    check_vector(
        "75650c19192e010202800c02013fe921fb323ae5afbfe921fb323ae5afe268", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":2,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_"
        "desc\":12,\"param_id\":2,\"type\":1,\"low_thres\":0.7853981,\"high_thres\":-0.7853981}}}]}\n");
}

TEST(Vectors, event_control_enable_2) {
    check_vector("75650c05052b0102011f84", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":43,\"name\":\"event_control\","
                 "\"values\":{\"function\":1,\"instance\":2,\"mode\":1}}]}\n");
}

TEST(Vectors, event_trigger_combination_any) {
    check_vector("75650c0b0b2e010303fffe0102000031f6", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
                 "\"values\":{\"function\":1,\"instance\":3,\"type\":3,\"parameters\":{\"logic_table\":65534,"
                 "\"input_triggers\":[1,2,0,0]}}}]}\n");
}

TEST(Vectors, event_control_enable_3) {
    check_vector("75650c05052b0103012086", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":43,\"name\":\"event_control\","
                 "\"values\":{\"function\":1,\"instance\":3,\"mode\":1}}]}\n");
}

TEST(Vectors, event_action_gpio_trigger_3) {
    check_vector("75650c08082f010103010401303f", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":1,\"trigger\":3,\"type\":1,\"parameters\":{\"pin\":"
                 "4,\"mode\":1}}}]}\n");
}

TEST(Vectors, event_trigger_threshold_roll_10) {
    check_vector(
        "75650c19192e010202800c0101bfc6571814c9bba03fc6571814c9bba0b1fa", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":2,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_"
        "desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":-0.1745329,\"high_thres\":0.1745329}}}]}\n");
}

TEST(Vectors, event_trigger_combination_latch) {
    check_vector("75650c0b0b2e010303cece03010200d3e9", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
                 "\"values\":{\"function\":1,\"instance\":3,\"type\":3,\"parameters\":{\"logic_table\":52942,"
                 "\"input_triggers\":[3,1,2,0]}}}]}\n");
}

TEST(Vectors, event_action_gpio_oneshot_low) {
    check_vector("75650c08082f0102020104063545", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":47,\"name\":\"event_action_config\","
                 "\"values\":{\"function\":1,\"instance\":2,\"trigger\":2,\"type\":1,\"parameters\":{\"pin\":"
                 "4,\"mode\":6}}}]}\n");
}

TEST(Vectors, event_trigger_config_read) {
    check_vector("75650c04042e02011f66", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
                 "\"values\":{\"function\":2,\"instance\":1}}]}\n");
}

TEST(Vectors, event_trigger_config_read_reply_none) {
    check_vector("75650c0804f12e0004b80100ce98", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":46,\"ack_code\":0}},{\"descriptor\":184,\"name\":\"event_trigger_"
                 "config_response\",\"values\":{\"instance\":1,\"type\":0,\"parameters\":null}}]}\n");
}

TEST(Vectors, get_event_action_status_all_reply) {
    check_vector("75650c0b04f12d0007b70202010103da41", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
                 "\"command_descriptor\":45,\"ack_code\":0}},{\"descriptor\":183,\"name\":\"event_action_"
                 "status\",\"values\":{\"count\":2,\"actions\":[{\"action_type\":2,\"trigger_id\":1},{"
                 "\"action_type\":1,\"trigger_id\":3}]}}]}\n");
}

TEST(Vectors, doubles_power_of_two_and_negative_zero) {
    check_vector("75650c19192e010402800c010116900000000000008000000000000000014c", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
                 "\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,"
                 "\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":5.225680706521042e-200,\"high_"
                 "thres\":-0.0}}}]}\n");
}

TEST(Vectors, doubles_denormal_and_1e16) {
    check_vector(
        "75650c19192e010402800c010100000000000000014341c37937e0800033cf", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_"
        "desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":5e-324,\"high_thres\":1e+16}}}]}\n");
}

TEST(Vectors, doubles_positional_boundary) {
    check_vector(
        "75650c19192e010402800c01013f1a36e2eb1c432d3ee4f8b588e368f156da", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_"
        "desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":0.0001,\"high_thres\":1e-05}}}]}\n");
}

TEST(Vectors, doubles_large_values) {
    check_vector(
        "75650c19192e010402800c01017e37e43c8800759c42dc12218377de6bdd44", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
        "\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,\"field_"
        "desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":1e+300,\"high_thres\":123456789012345.67}}}]}\n");
}

TEST(Vectors, doubles_infinity_and_nan_payload) {
    check_vector("75650c19192e010402800c01017ff0000000000000fff00000000000013a05", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"name\":\"event_trigger_config\","
                 "\"values\":{\"function\":1,\"instance\":4,\"type\":2,\"parameters\":{\"desc_set\":128,"
                 "\"field_desc\":12,\"param_id\":1,\"type\":1,\"low_thres\":\"inf\",\"high_thres\":\"nan:"
                 "0xfff0000000000001\"}}}]}\n");
}

TEST(Vectors, overview_field_descriptor_0x03) {
    check_vector("7565800e0e033e7a63a0bb8e3b297fe5bf7f83e1", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":3,\"data\":"
                 "\"3e7a63a0bb8e3b297fe5bf7f\",\"error\":\"unknown descriptor\"}]}\n");
}

TEST(Vectors, overview_scaled_mag) {
    check_vector("7565800e0e063e7a63a0bb8e3b297fe5bf7f8608", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":"
                 "{\"scaled_mag\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}\n");
}

TEST(Vectors, overview_gyro_mag_published) {
    check_vector("7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fe0c6", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":"
                 "\"7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fe0c6\"}\n");
}

TEST(Vectors, overview_gyro_mag) {
    check_vector("7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fb11e", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":5,\"name\":\"scaled_gyro\","
                 "\"values\":{\"scaled_gyro\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}"
                 ",{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":{\"scaled_mag\":[0.2445206642150879,-"
                 "0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}\n");
}

TEST(Vectors, scaled_accel_example_gx5_published) {
    check_vector("7565800e0e043e7a63a0bb8e3b297fe5bf7f92c0", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"7565800e0e043e7a63a0bb8e3b297fe5bf7f92c0\"}\n");
}

TEST(Vectors, scaled_accel_example) {
    check_vector(
        "7565800e0e043e7a63a0bb8e3b297fe5bf7f84ee", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{"
        "\"scaled_accel\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}\n");
}

TEST(Vectors, poll_imu_data_packet_published) {
    check_vector("7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7f41bb", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":"
                 "\"7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7f41bb\"}\n");
}

TEST(Vectors, poll_imu_data_packet_as_printed) {
    check_vector(
        "7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7faddc", MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{"
        "\"scaled_accel\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}},{\"descriptor\":3,"
        "\"data\":\"3e7a63a0bb8e3b297fe5bf7f\",\"error\":\"unknown descriptor\"}]}\n");
}

TEST(Vectors, poll_imu_data_packet_corrected) {
    check_vector("7565801c0e053e7a63a0bb8e3b297fe5bf7f0e043e7a63a0bb8e3b297fe5bf7faf04", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":5,\"name\":\"scaled_gyro\","
                 "\"values\":{\"scaled_gyro\":[0.2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}"
                 ",{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0."
                 "2445206642150879,-0.004340548533946276,\"nan:0x7fe5bf7f\"]}}]}\n");
}

TEST(Vectors, accel_gyro_mag_typical) {
    check_vector(
        "7565802a0e043f800000bf000000000000000e053e8000003a83126fc00000000e063f0000003e000000bec00000f2e2",
        MIP_DEVICE_ANY,
        "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{"
        "\"scaled_accel\":[1.0,-0.5,0.0]}},{\"descriptor\":5,\"name\":\"scaled_gyro\",\"values\":{\"scaled_"
        "gyro\":[0.25,0.0010000000474974513,-2.0]}},{\"descriptor\":6,\"name\":\"scaled_mag\",\"values\":{"
        "\"scaled_mag\":[0.5,0.125,-0.375]}}]}\n");
}

TEST(Vectors, garbage_around_ping) {
    check_vector("00ff756501020201e0c675", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"00ff\"}\n{\"offset\":2,\"set\":1,\"fields\":[{\"descriptor\":1,"
                 "\"name\":\"ping\",\"values\":{}}]}\n{\"offset\":10,\"skipped\":\"75\"}\n");
}

TEST(Vectors, false_sync_running_past_the_end) {
    check_vector("75650110756501020201e0c6", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"75650110\"}\n{\"offset\":4,\"set\":1,\"fields\":[{"
                 "\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Vectors, bad_checksum_then_valid) {
    check_vector(
        "756501020201e0c77565010404f10100d56a", MIP_DEVICE_ANY,
        "{\"offset\":0,\"skipped\":\"756501020201e0c7\"}\n{\"offset\":8,\"set\":1,\"fields\":[{"
        "\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}\n");
}

TEST(Vectors, packet_inside_false_packet) {
    check_vector(
        "7565010a756501020201e0c600000000", MIP_DEVICE_ANY,
        "{\"offset\":0,\"skipped\":\"7565010a\"}\n{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":1,"
        "\"name\":\"ping\",\"values\":{}}]}\n{\"offset\":12,\"skipped\":\"00000000\"}\n");
}

TEST(Vectors, truncated_packet_at_end) {
    check_vector("7565010404f1", MIP_DEVICE_ANY, "{\"offset\":0,\"skipped\":\"7565010404f1\"}\n");
}

TEST(Vectors, field_length_overruns_payload) {
    check_vector("7565010402010302e798", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}},{"
                 "\"trailing\":\"0302\",\"error\":\"field length 3 at payload offset 2 overruns the payload "
                 "(2 bytes left)\"}]}\n");
}

TEST(Vectors, field_length_below_header) {
    check_vector("756501020101dfc4", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"trailing\":\"0101\",\"error\":\"field length 1 at "
                 "payload offset 0 is shorter than the field header\"}]}\n");
}

TEST(Vectors, field_too_short_for_type) {
    check_vector("7565800a0a043f800000bf000000f0f1", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"data\":\"3f800000bf000000\","
                 "\"error\":\"scaled_accel[2]: needs 4 bytes at offset 8, 0 left\"}]}\n");
}

TEST(Vectors, field_with_trailing_bytes) {
    check_vector("756501030302553804", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"data\":\"55\",\"error\":\"1 "
                 "unexpected bytes at offset 0\"}]}\n");
}

TEST(Vectors, unknown_set_and_descriptor) {
    check_vector("7565a70404331234026a", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":167,\"fields\":[{\"descriptor\":51,\"data\":\"1234\",\"error\":"
                 "\"unknown descriptor set\"}]}\n");
}

TEST(Vectors, ack_in_undefined_command_set) {
    check_vector("75657f0404f11000627c", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":127,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":"
                 "{\"command_descriptor\":16,\"ack_code\":0}}]}\n");
}

TEST(Vectors, union_selector_without_member) {
    check_vector("75650c07072e0101090104320c", MIP_DEVICE_ANY,
                 "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":46,\"data\":\"0101090104\",\"error\":"
                 "\"parameters: no member for selector value 9\"}]}\n");
}
