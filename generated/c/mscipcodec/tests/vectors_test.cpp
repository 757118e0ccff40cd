// Golden vectors (tests/vectors/) and the stream corpus (tests/streams/): decode the bytes, fed
// whole and in chunks of every size from 1 byte up, and compare the exact JSON lines; encode the
// lines back and compare the bytes. Generated: do not edit.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace {

[[maybe_unused]] void check_vector(const char *hex, mscipc_device_t device, const char *expect) {
    using namespace test_support;
    std::vector<uint8_t> bytes = from_hex(hex);
    EXPECT_EQ(decode_text(bytes, 0, device), expect) << "decoded whole";
    // Every chunking: the events must not depend on how the input is split (the first size that
    // differs is reported, not every one).
    for (size_t chunk = 1; chunk < bytes.size(); ++chunk) {
        std::string got = decode_text(bytes, chunk, device);
        if (got != expect) {
            EXPECT_EQ(got, expect) << "decoded in chunks of " << chunk << " bytes";
            break;
        }
    }
    EXPECT_EQ(straight_line_mismatch(bytes), "") << "the straight-line decoders (issue 38)";
    std::vector<uint8_t> encoded;
    std::string error;
    ASSERT_TRUE(encode_text(expect, &encoded, &error)) << error;
    EXPECT_EQ(to_hex(encoded), hex) << "encoded from the expected lines";
}

} // namespace

TEST(Vectors, mscip_ping_command) {
    check_vector(
        "a5a5010202004f25", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Vectors, mscip_ping_reply) {
    check_vector("a5a5010480020200d3cf", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":2,\"error_code\":0}}]}\n");
}

TEST(Vectors, get_device_messages_command) {
    check_vector("a5a5010203005027", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"get_device_messages\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, get_device_messages_reply) {
    check_vector(
        "a5a5010e80020300830801020103010401057b57", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_"
        "code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"device_messages\",\"values\":{"
        "\"messages\":[{\"message_type\":1,\"message_code\":2},{\"message_type\":1,\"message_code\":3},{"
        "\"message_type\":1,\"message_code\":4},{\"message_type\":1,\"message_code\":5}]}}]}\n");
}

TEST(Vectors, get_device_messages_reply_published) {
    check_vector("a5a5010f80030300830801020103010401057d73", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a5010f80030300830801020103010401057d73\"}\n");
}

TEST(Vectors, get_device_messages_reply_table) {
    check_vector("a5a5010f80020300830801020103010401057d73", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a5010f80020300830801020103010401057d73\"}\n");
}

TEST(Vectors, get_device_messages_reply_full) {
    check_vector(
        "a5a5014080020300833a0102010301040105010601070108010902010203020402050206020702080209020a020b020c020d"
        "a281a282a283a284a285a286a287a288a289d169",
        MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_"
        "code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"device_messages\",\"values\":{"
        "\"messages\":[{\"message_type\":1,\"message_code\":2},{\"message_type\":1,\"message_code\":3},{"
        "\"message_type\":1,\"message_code\":4},{\"message_type\":1,\"message_code\":5},{\"message_type\":1,"
        "\"message_code\":6},{\"message_type\":1,\"message_code\":7},{\"message_type\":1,\"message_code\":8},"
        "{\"message_type\":1,\"message_code\":9},{\"message_type\":2,\"message_code\":1},{\"message_type\":2,"
        "\"message_code\":3},{\"message_type\":2,\"message_code\":4},{\"message_type\":2,\"message_code\":5},"
        "{\"message_type\":2,\"message_code\":6},{\"message_type\":2,\"message_code\":7},{\"message_type\":2,"
        "\"message_code\":8},{\"message_type\":2,\"message_code\":9},{\"message_type\":2,\"message_code\":10}"
        ",{\"message_type\":2,\"message_code\":11},{\"message_type\":2,\"message_code\":12},{\"message_"
        "type\":2,\"message_code\":13},{\"message_type\":162,\"message_code\":129},{\"message_type\":162,"
        "\"message_code\":130},{\"message_type\":162,\"message_code\":131},{\"message_type\":162,\"message_"
        "code\":132},{\"message_type\":162,\"message_code\":133},{\"message_type\":162,\"message_code\":134},"
        "{\"message_type\":162,\"message_code\":135},{\"message_type\":162,\"message_code\":136},{\"message_"
        "type\":162,\"message_code\":137}]}}]}\n");
}

TEST(Vectors, get_device_messages_reply_empty) {
    check_vector("a5a50106800203008300598d", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"device_messages\","
                 "\"values\":{\"messages\":[]}}]}\n");
}

TEST(Vectors, mscip_device_reset_command) {
    check_vector(
        "a5a5010204005129", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"device_reset\",\"values\":{}}]}\n");
}

TEST(Vectors, mscip_device_reset_reply) {
    check_vector("a5a5010480020400d5d3", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":4,\"error_code\":0}}]}\n");
}

TEST(Vectors, get_device_model_command) {
    check_vector("a5a501020500522b", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, get_device_model_reply) {
    check_vector("a5a501168002050085102020202020204d535f494d5533303230ec54", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":5,\"error_code\":0}},{\"descriptor\":133,\"name\":\"device_model\","
                 "\"values\":{\"model\":\"      MS_IMU3020\"}}]}\n");
}

TEST(Vectors, get_device_sn_command) {
    check_vector("a5a501020600532d", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":6,\"name\":\"get_device_sn\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, get_device_sn_reply) {
    check_vector("a5a5011680020600861020202020202020202020203230323638e123", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":6,\"error_code\":0}},{\"descriptor\":134,\"name\":\"device_sn\","
                 "\"values\":{\"serial_number\":\"           20268\"}}]}\n");
}

TEST(Vectors, get_device_sn_reply_published) {
    check_vector(
        "a5a501168002060086102020202020202020202020203230323638e123", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"skipped\":\"a5a501168002060086102020202020202020202020203230323638e123\"}\n");
}

TEST(Vectors, get_device_fw_command) {
    check_vector("a5a501020700542f", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":7,\"name\":\"get_device_fw\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, get_device_fw_reply) {
    check_vector("a5a50116800207008710202020202020202020525f315f325f33a625", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":7,\"error_code\":0}},{\"descriptor\":135,\"name\":\"device_fw\","
                 "\"values\":{\"firmware\":\"         R_1_2_3\"}}]}\n");
}

TEST(Vectors, get_device_fw_reply_published) {
    check_vector(
        "a5a501168002070087102020202020202020202020525f315f325f33a625", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"skipped\":\"a5a501168002070087102020202020202020202020525f315f325f33a625\"}\n");
}

TEST(Vectors, get_device_cal_command) {
    check_vector("a5a5010208005531", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":8,\"name\":\"get_device_cal\","
                 "\"values\":{}}]}\n");
}

TEST(Vectors, get_device_cal_reply) {
    check_vector("a5a5011680020800881020202020202030352d30382d323031353210", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":8,\"error_code\":0}},{\"descriptor\":136,\"name\":\"device_cal\","
                 "\"values\":{\"date\":\"      05-08-2015\"}}]}\n");
}

TEST(Vectors, get_device_cal_reply_published) {
    check_vector("a5a50116800208008810202020202030352d30382d323031353210", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a50116800208008810202020202030352d30382d323031353210\"}\n");
}

TEST(Vectors, correlate_gps_time_command) {
    check_vector("a5a501080906072f000002ff99af", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"correlate_gps_time\","
                 "\"values\":{\"week\":1839,\"seconds\":767}}]}\n");
}

TEST(Vectors, correlate_gps_time_reply) {
    check_vector("a5a5010480020900dadd", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":9,\"error_code\":0}}]}\n");
}

TEST(Vectors, mscip_nack_checksum_error) {
    check_vector("a5a5010480020201d4d0", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":2,\"error_code\":1}}]}\n");
}

TEST(Vectors, mscip_nack_invalid_message_type) {
    check_vector("a5a5030480020102d6db", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":3,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":1,\"error_code\":2}}]}\n");
}

TEST(Vectors, mscip_nack_invalid_message_code) {
    check_vector("a5a5010480020a03dee2", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":10,\"error_code\":3}}]}\n");
}

TEST(Vectors, mscip_nack_invalid_parameter) {
    check_vector("a5a5020480020104d7d7", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":1,\"error_code\":4}}]}\n");
}

TEST(Vectors, get_device_model_nack) {
    check_vector("a5a5010480020501d7d6", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":5,\"error_code\":1}}]}\n");
}

TEST(Vectors, correlate_gps_time_command_end_of_week) {
    check_vector("a5a501080906096000093a7f8dbb", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":9,\"name\":\"correlate_gps_time\","
                 "\"values\":{\"week\":2400,\"seconds\":604799}}]}\n");
}

TEST(Vectors, encode_input_irregular_size_byte) {
    check_vector("a5a502030500025688", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\","
                 "\"values\":{\"function\":2}}]}\n");
}

TEST(Vectors, uart_baud_rate_write) {
    check_vector("a5a502070105010001c2001d84", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\","
                 "\"values\":{\"function\":1,\"baud_rate\":115200}}]}\n");
}

TEST(Vectors, uart_baud_rate_write_reply) {
    check_vector("a5a5020480020100d3d3", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":1,\"error_code\":0}}]}\n");
}

TEST(Vectors, uart_baud_rate_read) {
    check_vector("a5a50203010102537e", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\","
                 "\"values\":{\"function\":2}}]}\n");
}

TEST(Vectors, uart_baud_rate_save) {
    check_vector("a5a50203010103547f", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\","
                 "\"values\":{\"function\":3}}]}\n");
}

TEST(Vectors, uart_baud_rate_load) {
    check_vector("a5a502030101045580", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\","
                 "\"values\":{\"function\":4}}]}\n");
}

TEST(Vectors, uart_baud_rate_default) {
    check_vector("a5a502030101055681", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\","
                 "\"values\":{\"function\":5}}]}\n");
}

TEST(Vectors, uart_baud_rate_read_reply) {
    check_vector("a5a5020a8002010081040001c20021a8", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":1,\"error_code\":0}},{\"descriptor\":129,\"name\":\"uart_baud_rate_"
                 "response\",\"values\":{\"baud_rate\":115200}}]}\n");
}

TEST(Vectors, uart_baud_rate_write_921600) {
    check_vector("a5a50207010501000e10007847", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"uart_baud_rate\","
                 "\"values\":{\"function\":1,\"baud_rate\":921600}}]}\n");
}

TEST(Vectors, filter_write) {
    check_vector("a5a502040302010258e1", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{"
                 "\"function\":1,\"bandwidth\":2}}]}\n");
}

TEST(Vectors, filter_write_reply) {
    check_vector("a5a5020480020300d5d7", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":3,\"error_code\":0}}]}\n");
}

TEST(Vectors, filter_read) {
    check_vector("a5a502030301025584", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{"
                 "\"function\":2}}]}\n");
}

TEST(Vectors, filter_save) {
    check_vector("a5a502030301035685", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{"
                 "\"function\":3}}]}\n");
}

TEST(Vectors, filter_load) {
    check_vector("a5a502030301045786", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{"
                 "\"function\":4}}]}\n");
}

TEST(Vectors, filter_default) {
    check_vector("a5a502030301055887", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{"
                 "\"function\":5}}]}\n");
}

TEST(Vectors, filter_read_reply) {
    check_vector("a5a50207800203008301025efb", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":3,\"error_code\":0}},{\"descriptor\":131,\"name\":\"filter_response\","
                 "\"values\":{\"bandwidth\":2}}]}\n");
}

TEST(Vectors, filter_write_disabled) {
    check_vector("a5a502040302010056df", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{"
                 "\"function\":1,\"bandwidth\":0}}]}\n");
}

TEST(Vectors, filter_save_with_placeholder) {
    check_vector("a5a50204030203075fea", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":3,\"name\":\"filter\",\"values\":{"
                 "\"function\":3,\"bandwidth\":7}}]}\n");
}

TEST(Vectors, sample_rate_write) {
    check_vector("a5a5020504030100126b56", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{"
                 "\"function\":1,\"decimation\":18}}]}\n");
}

TEST(Vectors, sample_rate_write_reply) {
    check_vector("a5a5020480020400d6d9", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":4,\"error_code\":0}}]}\n");
}

TEST(Vectors, sample_rate_read) {
    check_vector("a5a502030401025687", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{"
                 "\"function\":2}}]}\n");
}

TEST(Vectors, sample_rate_save) {
    check_vector("a5a502030401035788", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{"
                 "\"function\":3}}]}\n");
}

TEST(Vectors, sample_rate_load) {
    check_vector("a5a502030401045889", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{"
                 "\"function\":4}}]}\n");
}

TEST(Vectors, sample_rate_default) {
    check_vector("a5a50203040105598a", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{"
                 "\"function\":5}}]}\n");
}

TEST(Vectors, sample_rate_read_reply) {
    check_vector("a5a5020880020400840200086873", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":4,\"error_code\":0}},{\"descriptor\":132,\"name\":\"sample_rate_"
                 "response\",\"values\":{\"decimation\":8}}]}\n");
}

TEST(Vectors, sample_rate_write_100hz) {
    check_vector("a5a502050403010008614c", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":4,\"name\":\"sample_rate\",\"values\":{"
                 "\"function\":1,\"decimation\":8}}]}\n");
}

TEST(Vectors, select_sensors_write) {
    check_vector("a5a502060503010081825e2e", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\","
                 "\"values\":{\"function\":1,\"reserved\":0,\"sensors\":[129,130]}}]}\n");
}

TEST(Vectors, select_sensors_write_reply) {
    check_vector("a5a5020480020500d7db", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":5,\"error_code\":0}}]}\n");
}

TEST(Vectors, select_sensors_read) {
    check_vector("a5a502030500025688", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\","
                 "\"values\":{\"function\":2}}]}\n");
}

TEST(Vectors, select_sensors_save) {
    check_vector("a5a502030500035789", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\","
                 "\"values\":{\"function\":3}}]}\n");
}

TEST(Vectors, select_sensors_load) {
    check_vector("a5a50203050004588a", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\","
                 "\"values\":{\"function\":4}}]}\n");
}

TEST(Vectors, select_sensors_default) {
    check_vector("a5a50203050005598b", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\","
                 "\"values\":{\"function\":5}}]}\n");
}

TEST(Vectors, select_sensors_read_reply) {
    check_vector("a5a50208800205008502818265f9", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":5,\"error_code\":0}},{\"descriptor\":133,\"name\":\"select_sensors_"
                 "response\",\"values\":{\"sensors\":[129,130]}}]}\n");
}

TEST(Vectors, select_sensors_write_several) {
    check_vector("a5a5020a050701008182868788847f37", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":5,\"name\":\"select_sensors\","
                 "\"values\":{\"function\":1,\"reserved\":0,\"sensors\":[129,130,134,135,136,132]}}]}\n");
}

TEST(Vectors, get_internal_sample_rate_command) {
    check_vector("a5a5020206005431", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":6,\"name\":\"get_internal_sample_"
                 "rate\",\"values\":{}}]}\n");
}

TEST(Vectors, get_internal_sample_rate_reply) {
    check_vector("a5a50208800206008602032087a5", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":6,\"error_code\":0}},{\"descriptor\":134,\"name\":\"internal_sample_"
                 "rate\",\"values\":{\"rate\":800}}]}\n");
}

TEST(Vectors, get_internal_sample_rate_reply_1000hz) {
    check_vector("a5a5020880020600860203e84f6d", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":6,\"error_code\":0}},{\"descriptor\":134,\"name\":\"internal_sample_"
                 "rate\",\"values\":{\"rate\":1000}}]}\n");
}

TEST(Vectors, accel_range_write) {
    check_vector("a5a50204070201025cf1", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{"
                 "\"function\":1,\"range\":2}}]}\n");
}

TEST(Vectors, accel_range_write_reply) {
    check_vector("a5a5020480020700d9df", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":7,\"error_code\":0}}]}\n");
}

TEST(Vectors, accel_range_read) {
    check_vector("a5a502030701025990", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{"
                 "\"function\":2}}]}\n");
}

TEST(Vectors, accel_range_save) {
    check_vector("a5a502030701035a91", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{"
                 "\"function\":3}}]}\n");
}

TEST(Vectors, accel_range_load) {
    check_vector("a5a502030701045b92", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{"
                 "\"function\":4}}]}\n");
}

TEST(Vectors, accel_range_default) {
    check_vector("a5a502030701055c93", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":7,\"name\":\"accel_range\",\"values\":{"
                 "\"function\":5}}]}\n");
}

TEST(Vectors, accel_range_read_reply) {
    check_vector("a5a5020780020700870102661b", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":7,\"error_code\":0}},{\"descriptor\":135,\"name\":\"accel_range_"
                 "response\",\"values\":{\"range\":2}}]}\n");
}

TEST(Vectors, gyro_range_write) {
    check_vector("a5a50204080201025df5", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{"
                 "\"function\":1,\"range\":2}}]}\n");
}

TEST(Vectors, gyro_range_write_reply) {
    check_vector("a5a5020480020800dae1", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":8,\"error_code\":0}}]}\n");
}

TEST(Vectors, gyro_range_read) {
    check_vector("a5a502030801025a93", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{"
                 "\"function\":2}}]}\n");
}

TEST(Vectors, gyro_range_save) {
    check_vector("a5a502030801035b94", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{"
                 "\"function\":3}}]}\n");
}

TEST(Vectors, gyro_range_load) {
    check_vector("a5a502030801045c95", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{"
                 "\"function\":4}}]}\n");
}

TEST(Vectors, gyro_range_default) {
    check_vector("a5a502030801055d96", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":8,\"name\":\"gyro_range\",\"values\":{"
                 "\"function\":5}}]}\n");
}

TEST(Vectors, gyro_range_read_reply) {
    check_vector("a5a50207800208008801026823", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":8,\"error_code\":0}},{\"descriptor\":136,\"name\":\"gyro_range_response\","
                 "\"values\":{\"range\":2}}]}\n");
}

TEST(Vectors, config_all_save) {
    check_vector("a5a502030901035c97", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":9,\"name\":\"config_all\",\"values\":{"
                 "\"function\":3}}]}\n");
}

TEST(Vectors, config_all_reply) {
    check_vector("a5a5020480020900dbe3", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":9,\"error_code\":0}}]}\n");
}

TEST(Vectors, config_all_load) {
    check_vector("a5a502030901045d98", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":9,\"name\":\"config_all\",\"values\":{"
                 "\"function\":4}}]}\n");
}

TEST(Vectors, config_all_default) {
    check_vector("a5a502030901055e99", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":9,\"name\":\"config_all\",\"values\":{"
                 "\"function\":5}}]}\n");
}

TEST(Vectors, data_on_off_write) {
    check_vector("a5a502040a0201015efc", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":"
                 "{\"function\":1,\"control\":1}}]}\n");
}

TEST(Vectors, data_on_off_write_reply) {
    check_vector("a5a5020480020a00dce5", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":10,\"error_code\":0}}]}\n");
}

TEST(Vectors, data_on_off_read) {
    check_vector("a5a502030a01025c99", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":"
                 "{\"function\":2}}]}\n");
}

TEST(Vectors, data_on_off_save) {
    check_vector("a5a502030a01035d9a", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":"
                 "{\"function\":3}}]}\n");
}

TEST(Vectors, data_on_off_load) {
    check_vector("a5a502030a01045e9b", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":"
                 "{\"function\":4}}]}\n");
}

TEST(Vectors, data_on_off_default) {
    check_vector("a5a502030a01055f9c", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":"
                 "{\"function\":5}}]}\n");
}

TEST(Vectors, data_on_off_read_reply) {
    check_vector("a5a5020780020a008a01016b32", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":10,\"error_code\":0}},{\"descriptor\":138,\"name\":\"data_on_off_"
                 "response\",\"values\":{\"control\":1}}]}\n");
}

TEST(Vectors, data_on_off_write_off) {
    check_vector("a5a502040a0201005dfb", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":10,\"name\":\"data_on_off\",\"values\":"
                 "{\"function\":1,\"control\":0}}]}\n");
}

TEST(Vectors, xtrig_on_off_write) {
    check_vector("a5a502040b0201015f00", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\","
                 "\"values\":{\"function\":1,\"control\":1}}]}\n");
}

TEST(Vectors, xtrig_on_off_write_reply) {
    check_vector("a5a5020480020b00dde7", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":11,\"error_code\":0}}]}\n");
}

TEST(Vectors, xtrig_on_off_read) {
    check_vector("a5a502030b01025d9c", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\","
                 "\"values\":{\"function\":2}}]}\n");
}

TEST(Vectors, xtrig_on_off_save) {
    check_vector("a5a502030b01035e9d", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\","
                 "\"values\":{\"function\":3}}]}\n");
}

TEST(Vectors, xtrig_on_off_load) {
    check_vector("a5a502030b01045f9e", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\","
                 "\"values\":{\"function\":4}}]}\n");
}

TEST(Vectors, xtrig_on_off_default) {
    check_vector("a5a502030b0105609f", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\","
                 "\"values\":{\"function\":5}}]}\n");
}

TEST(Vectors, xtrig_on_off_read_reply) {
    check_vector("a5a5020780020b008b01006c39", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":11,\"error_code\":0}},{\"descriptor\":139,\"name\":\"xtrig_on_off_"
                 "response\",\"values\":{\"control\":0}}]}\n");
}

TEST(Vectors, xtrig_on_off_write_off) {
    check_vector("a5a502040b0201005eff", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":11,\"name\":\"xtrig_on_off\","
                 "\"values\":{\"function\":1,\"control\":0}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_write) {
    check_vector("a5a502050c0301818264f0", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\","
                 "\"values\":{\"function\":1,\"sensors\":[129,130]}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_write_reply) {
    check_vector("a5a5020480020c00dee9", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":12,\"error_code\":0}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_read) {
    check_vector("a5a502030c01025e9f", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\","
                 "\"values\":{\"function\":2}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_save) {
    check_vector("a5a502030c01035fa0", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\","
                 "\"values\":{\"function\":3}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_load) {
    check_vector("a5a502030c010460a1", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\","
                 "\"values\":{\"function\":4}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_default) {
    check_vector("a5a502030c010561a2", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\","
                 "\"values\":{\"function\":5}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_read_reply) {
    check_vector("a5a5020980020c008c03818289fe49", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":12,\"error_code\":0}},{\"descriptor\":140,\"name\":\"select_sensors_rev_b_"
                 "response\",\"values\":{\"sensors\":[129,130,137]}}]}\n");
}

TEST(Vectors, select_sensors_rev_b_write_all) {
    check_vector("a5a5020c0c0a018182838485868788891ce0", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\","
                 "\"values\":{\"function\":1,\"sensors\":[129,130,131,132,133,134,135,136,137]}}]}\n");
}

TEST(Vectors, aux_accel_range_write) {
    check_vector("a5a502040d020105650c", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\","
                 "\"values\":{\"function\":1,\"range\":5}}]}\n");
}

TEST(Vectors, aux_accel_range_write_reply) {
    check_vector("a5a5020480020d00dfeb", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":13,\"error_code\":0}}]}\n");
}

TEST(Vectors, aux_accel_range_read) {
    check_vector("a5a502030d01025fa2", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\","
                 "\"values\":{\"function\":2}}]}\n");
}

TEST(Vectors, aux_accel_range_save) {
    check_vector("a5a502030d010360a3", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\","
                 "\"values\":{\"function\":3}}]}\n");
}

TEST(Vectors, aux_accel_range_load) {
    check_vector("a5a502030d010461a4", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\","
                 "\"values\":{\"function\":4}}]}\n");
}

TEST(Vectors, aux_accel_range_default) {
    check_vector("a5a502030d010562a5", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":13,\"name\":\"aux_accel_range\","
                 "\"values\":{\"function\":5}}]}\n");
}

TEST(Vectors, aux_accel_range_read_reply) {
    check_vector("a5a5020780020d008d0105754e", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"command_code\":13,\"error_code\":0}},{\"descriptor\":141,\"name\":\"aux_accel_range_"
                 "response\",\"values\":{\"range\":5}}]}\n");
}

TEST(Vectors, imu_data_default) {
    check_vector("a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\","
                 "\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},"
                 "{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":[1.9999999494757503e-05,"
                 "1.4999999621068127e-05,1.2000000424450263e-05]}}]}\n");
}

TEST(Vectors, scaled_accel) {
    check_vector(
        "a5a5a20e810c37a7c5ac377ba8823f800065d61a", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{"
        "\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}}]}\n");
}

TEST(Vectors, scaled_gyro) {
    check_vector(
        "a5a5a20e820c37a7c5ac377ba8823749539c2240", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{"
        "\"gyro\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}\n");
}

TEST(Vectors, scaled_mag) {
    check_vector(
        "a5a5a20e830c37a7c5ac377ba8823749539c234e", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":131,\"name\":\"scaled_mag\",\"values\":{"
        "\"mag\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}\n");
}

TEST(Vectors, delta_theta) {
    check_vector(
        "a5a5a20e840c37a7c5ac377ba8823749539c245c", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":132,\"name\":\"delta_theta\",\"values\":{"
        "\"delta_theta\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}\n");
}

TEST(Vectors, delta_velocity) {
    check_vector(
        "a5a5a20e850c37a7c5ac377ba8823749539c256a", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":133,\"name\":\"delta_velocity\",\"values\":{"
        "\"delta_velocity\":[1.9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}\n");
}

TEST(Vectors, scaled_aux_accel) {
    check_vector(
        "a5a5a20e890c37a7c5ac377ba8823f800065de8a", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":137,\"name\":\"scaled_aux_accel\",\"values\":{"
        "\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}}]}\n");
}

TEST(Vectors, scaled_pressure_published) {
    check_vector("a5a5a2068604000003fd7cb4", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":134,\"name\":\"scaled_pressure\","
                 "\"values\":{\"pressure\":1.4307257320756382e-42}}]}\n");
}

TEST(Vectors, scaled_pressure) {
    check_vector("a5a5a2068604447f40007fbe", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":134,\"name\":\"scaled_pressure\","
                 "\"values\":{\"pressure\":1021.0}}]}\n");
}

TEST(Vectors, scaled_temperature_published) {
    check_vector("a5a5a20687040000001996d0", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":135,\"name\":\"scaled_temperature\","
                 "\"values\":{\"temperature\":3.5032461608120427e-44}}]}\n");
}

TEST(Vectors, scaled_temperature) {
    check_vector("a5a5a206870441c800008613", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":135,\"name\":\"scaled_temperature\","
                 "\"values\":{\"temperature\":25.0}}]}\n");
}

TEST(Vectors, gps_correlated_time_published) {
    check_vector("a5a5a20e880c410944c000000000072f00081a32", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a5a20e880c410944c000000000072f00081a32\"}\n");
}

TEST(Vectors, gps_correlated_time) {
    check_vector("a5a5a20e880c410944c000000000072f00081a15", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\","
                 "\"values\":{\"seconds\":207000.0,\"week\":1839,\"flags\":8}}]}\n");
}

TEST(Vectors, gps_correlated_time_not_set) {
    check_vector("a5a5a20e880c4028b0a3d70a3d7100000004dc85", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\","
                 "\"values\":{\"seconds\":12.345,\"week\":0,\"flags\":4}}]}\n");
}

TEST(Vectors, gps_correlated_time_set_and_pps) {
    check_vector("a5a5a20e880c410944c00a3d70a4072f000370df", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\","
                 "\"values\":{\"seconds\":207000.005,\"week\":1839,\"flags\":3}}]}\n");
}

TEST(Vectors, imu_data_gps_accel_temperature) {
    check_vector("a5a5a222880c410944c000000000072f0000810c00000000bf0000003f800000870441c80000c52b",
                 MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":136,\"name\":\"gps_correlated_time\","
                 "\"values\":{\"seconds\":207000.0,\"week\":1839,\"flags\":0}},{\"descriptor\":129,\"name\":"
                 "\"scaled_accel\",\"values\":{\"accel\":[0.0,-0.5,1.0]}},{\"descriptor\":135,\"name\":"
                 "\"scaled_temperature\",\"values\":{\"temperature\":25.0}}]}\n");
}

TEST(Vectors, imu_data_all_fields) {
    check_vector(
        "a5a5a26e810c3c800000be8000003f800000820c3f000000bfc0000042b40000830c3e8000003d800000bf000000840c3a80"
        "0000bb00000000000000850c3ba0000000000000bc2000008604447d50008704c2220000880c412274fffd70a3d709600001"
        "890cc0000000408000003e0000001011",
        MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{"
        "\"accel\":[0.015625,-0.25,1.0]}},{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":["
        "0.5,-1.5,90.0]}},{\"descriptor\":131,\"name\":\"scaled_mag\",\"values\":{\"mag\":[0.25,0.0625,-0.5]}"
        "},{\"descriptor\":132,\"name\":\"delta_theta\",\"values\":{\"delta_theta\":[0.0009765625,-0."
        "001953125,0.0]}},{\"descriptor\":133,\"name\":\"delta_velocity\",\"values\":{\"delta_velocity\":[0."
        "0048828125,0.0,-0.009765625]}},{\"descriptor\":134,\"name\":\"scaled_pressure\",\"values\":{"
        "\"pressure\":1013.25}},{\"descriptor\":135,\"name\":\"scaled_temperature\",\"values\":{"
        "\"temperature\":-40.5}},{\"descriptor\":136,\"name\":\"gps_correlated_time\",\"values\":{"
        "\"seconds\":604799.995,\"week\":2400,\"flags\":1}},{\"descriptor\":137,\"name\":\"scaled_aux_"
        "accel\",\"values\":{\"accel\":[-2.0,4.0,0.125]}}]}\n");
}

TEST(Streams, mscip_garbage_around_packets) {
    check_vector("00ff13a5a5010202004f2555a5a5010480020200d3cfa5", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"00ff13\"}\n{\"offset\":3,\"set\":1,\"fields\":[{\"descriptor\":"
                 "2,\"name\":\"ping\",\"values\":{}}]}\n{\"offset\":11,\"skipped\":\"55\"}\n{\"offset\":12,"
                 "\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,"
                 "\"error_code\":0}}]}\n{\"offset\":22,\"skipped\":\"a5\"}\n");
}

TEST(Streams, mscip_false_sync_running_past_the_end) {
    check_vector("a5a50130a5a5010202004f25", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a50130\"}\n{\"offset\":4,\"set\":1,\"fields\":[{"
                 "\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Streams, mscip_false_sync_bad_checksum_packet_inside) {
    check_vector(
        "a5a5010aa5a5010202004f2500000000", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"skipped\":\"a5a5010a\"}\n{\"offset\":4,\"set\":1,\"fields\":[{\"descriptor\":2,"
        "\"name\":\"ping\",\"values\":{}}]}\n{\"offset\":12,\"skipped\":\"00000000\"}\n");
}

TEST(Streams, mscip_extra_sync_byte) {
    check_vector("a5a5a5010202004f25", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5\"}\n{\"offset\":1,\"set\":1,\"fields\":[{\"descriptor\":2,"
                 "\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Streams, mscip_packets_back_to_back) {
    check_vector(
        "a5a502050c0301818264f0a5a5020480020c00dee9a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba88237"
        "49539c0c23a5a5a21c810c37a7c5ac377ba8823f800065820c37a7c5ac377ba8823749539c0c23",
        MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":12,\"name\":\"select_sensors_rev_b\",\"values\":"
        "{\"function\":1,\"sensors\":[129,130]}}]}\n{\"offset\":11,\"set\":2,\"fields\":[{\"descriptor\":128,"
        "\"name\":\"ack\",\"values\":{\"command_code\":12,\"error_code\":0}}]}\n{\"offset\":21,\"set\":162,"
        "\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1."
        "9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}},{\"descriptor\":130,\"name\":"
        "\"scaled_gyro\",\"values\":{\"gyro\":[1.9999999494757503e-05,1.4999999621068127e-05,1."
        "2000000424450263e-05]}}]}\n{\"offset\":55,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":"
        "\"scaled_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1."
        "0000120401382446]}},{\"descriptor\":130,\"name\":\"scaled_gyro\",\"values\":{\"gyro\":[1."
        "9999999494757503e-05,1.4999999621068127e-05,1.2000000424450263e-05]}}]}\n");
}

TEST(Streams, mscip_mip_packet_in_mscip_stream) {
    check_vector("a5a5010202004f25756501020201e0c6a5a5010480020200d3cf", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}\n{"
                 "\"offset\":8,\"skipped\":\"756501020201e0c6\"}\n{\"offset\":16,\"set\":1,\"fields\":[{"
                 "\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}\n");
}

TEST(Streams, mscip_bad_checksum_then_valid) {
    check_vector("a5a5010480020200d3cea5a5010480020200d3cf", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a5010480020200d3ce\"}\n{\"offset\":10,\"set\":1,\"fields\":[{"
                 "\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}\n");
}

TEST(Streams, mscip_truncated_packet_at_end) {
    check_vector("a5a50104800202", MSCIPC_DEVICE_ANY, "{\"offset\":0,\"skipped\":\"a5a50104800202\"}\n");
}

TEST(Streams, mscip_field_header_cut_short) {
    check_vector(
        "a5a50103020080d0f8", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}},{"
        "\"trailing\":\"80\",\"error\":\"field header at payload offset 2 needs 2 bytes, 1 left\"}]}\n");
}

TEST(Streams, mscip_field_size_overruns_payload) {
    check_vector("a5a5010480030200d4d2", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"trailing\":\"80030200\",\"error\":\"field length 3 "
                 "at payload offset 0 overruns the payload (4 bytes left)\"}]}\n");
}

TEST(Streams, mscip_field_too_short_for_type) {
    check_vector("a5a5a2048602447f3bb0", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":134,\"data\":\"447f\",\"error\":"
                 "\"pressure: needs 4 bytes at offset 0, 2 left\"}]}\n");
}

TEST(Streams, mscip_field_with_trailing_bytes) {
    check_vector("a5a50103020155a6cf", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"data\":\"55\",\"error\":\"1 "
                 "unexpected bytes at offset 0\"}]}\n");
}

TEST(Streams, mscip_message_list_with_half_entry) {
    check_vector("a5a501058303010201dabd", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":131,\"data\":\"010201\",\"error\":"
                 "\"messages: 3 bytes left at offset 0, not a multiple of 2\"}]}\n");
}

TEST(Streams, mscip_unknown_message_code) {
    check_vector("a5a501020a005735", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":10,\"data\":\"\",\"error\":\"unknown "
                 "descriptor\"}]}\n");
}

TEST(Streams, mscip_ack_code_in_data_message) {
    check_vector("a5a5a204800202007495", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":128,\"data\":\"0200\",\"error\":"
                 "\"unknown descriptor\"}]}\n");
}

TEST(Streams, mscip_unknown_message_type) {
    check_vector("a5a5a30681043f8000003717", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":163,\"fields\":[{\"descriptor\":129,\"data\":\"3f800000\",\"error\":"
                 "\"unknown descriptor set\"}]}\n");
}

TEST(Streams, mscip_select_sensors_rev_a_with_a_regular_size_byte) {
    check_vector("a5a502060504010081825f33", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":2,\"fields\":[{\"trailing\":\"050401008182\",\"error\":\"field "
                 "length 4 at payload offset 0 overruns the payload (6 bytes left)\"}]}\n");
}

TEST(Streams, mscip_empty_stream) {
    check_vector("", MSCIPC_DEVICE_ANY, "");
}

TEST(Streams, mscip_garbage_inside_packet) {
    check_vector("a5a50102aabbcc02004f25a5a5010202004f25", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a50102aabbcc02004f25\"}\n{\"offset\":11,\"set\":1,\"fields\":"
                 "[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Streams, mscip_sync_bytes_inside_a_valid_payload) {
    check_vector(
        "a5a5a2067e04a5a5a5a508f3a5a5010202004f25", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":126,\"data\":\"a5a5a5a5\",\"error\":\"unknown "
        "descriptor\"}]}\n{\"offset\":12,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\","
        "\"values\":{}}]}\n");
}

TEST(Streams, mscip_false_sync_of_maximum_length) {
    check_vector("a5a5a2ffa5a5010202004f25a5a5010202004f25", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"skipped\":\"a5a5a2ff\"}\n{\"offset\":4,\"set\":1,\"fields\":[{"
                 "\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}\n{\"offset\":12,\"set\":1,\"fields\":[{"
                 "\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Streams, mscip_longest_legal_packet) {
    check_vector(
        "a5a5a2ff810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f80"
        "0000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf0000004000"
        "0000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000"
        "bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000"
        "810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00000040000000810c3f800000bf00"
        "0000400000007e0100b03fa5a5010202004f25",
        MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{"
        "\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,"
        "-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{"
        "\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":"
        "129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":"
        "\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_"
        "accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\","
        "\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{"
        "\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,"
        "-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{"
        "\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":"
        "129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":"
        "\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_"
        "accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\","
        "\"values\":{\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{"
        "\"accel\":[1.0,-0.5,2.0]}},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,"
        "-0.5,2.0]}},{\"descriptor\":126,\"data\":\"00\",\"error\":\"unknown "
        "descriptor\"}]}\n{\"offset\":261,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\","
        "\"values\":{}}]}\n");
}

TEST(Streams, mscip_empty_payloads) {
    check_vector("a5a5a200ecc7a5a501004b85", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":162,\"fields\":[]}\n{\"offset\":6,\"set\":1,\"fields\":[]}\n");
}

TEST(Streams, mscip_zero_length_fields) {
    check_vector(
        "a5a5a21281007e00810c3f800000bf0000004000000048bd", MSCIPC_DEVICE_ANY,
        "{\"offset\":0,\"set\":162,\"fields\":[{\"descriptor\":129,\"data\":\"\",\"error\":\"accel[0]: needs "
        "4 bytes at offset 0, 0 left\"},{\"descriptor\":126,\"data\":\"\",\"error\":\"unknown "
        "descriptor\"},{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.0,-0.5,2.0]}}]}"
        "\n");
}

TEST(Streams, mscip_unknown_command_set) {
    check_vector("a5a555020200a375", MSCIPC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":85,\"fields\":[{\"descriptor\":2,\"data\":\"\",\"error\":\"unknown "
                 "descriptor set\"}]}\n");
}
