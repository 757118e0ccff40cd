// Golden vectors (tests/vectors/) and the stream corpus (tests/streams/): decode the bytes, fed
// whole and in chunks of every size from 1 byte up, and compare the exact JSON lines; encode the
// lines back and compare the bytes. Generated: do not edit.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace {

[[maybe_unused]] void check_vector(const char *hex, democ_device_t device, const char *expect) {
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

TEST(Vectors, demo_ping_command) {
    check_vector(
        "a5a5010201004e23", DEMOC_DEVICE_ANY,
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}\n");
}

TEST(Vectors, demo_ack) {
    check_vector("a5a5010480020100d2cd", DEMOC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{"
                 "\"echo\":1,\"code\":0}}]}\n");
}

TEST(Vectors, demo_configure_write_gpio) {
    check_vector("a5a501080206010101050100647f", DEMOC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"configure\",\"values\":{"
                 "\"function\":1,\"instance\":1,\"mode\":1,\"params\":{\"pin\":5,\"polarity\":true},"
                 "\"suppress_ack\":false}}]}\n");
}

TEST(Vectors, demo_configure_write_none) {
    check_vector("a5a501060204010200015b9c", DEMOC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"configure\",\"values\":{"
                 "\"function\":1,\"instance\":2,\"mode\":0,\"params\":null,\"suppress_ack\":true}}]}\n");
}

TEST(Vectors, demo_configure_read) {
    check_vector("a5a501040202020358da", DEMOC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"configure\",\"values\":{"
                 "\"function\":2,\"instance\":3}}]}\n");
}

TEST(Vectors, demo_configuration_response) {
    check_vector("a5a5017f827d0102006400c8616263000000000020202020202020202020206c6162656c3ff0000000000000000"
                 "0000000000000000000000000000000000000000000003ff0000000000000000000000000000000000000000000"
                 "0000000000000000003ff000000000000000000001ffffffff00000002fffffffe3001ffff78797a9f15",
                 DEMOC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":130,\"name\":\"configuration\","
                 "\"values\":{\"instance\":1,\"count\":2,\"rates\":[100,200],\"name\":"
                 "\"abc\\u0000\\u0000\\u0000\\u0000\\u0000\",\"label\":\"           "
                 "label\",\"matrix\":[1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0],\"fixed\":[1,-1,2,-2],\"flags\":"
                 "12289,\"signed\":-1,\"tail\":[\"x\",\"y\",\"z\"]}}]}\n");
}

TEST(Vectors, demo_per_device_dev_a) {
    check_vector("a5a5010603040102030462ab", DEMOC_DEVICE_DEV_A,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"per_device\",\"device\":"
                 "\"dev_a\",\"values\":{\"a\":16909060}}]}\n");
}

TEST(Vectors, demo_per_device_dev_b_with_extra) {
    check_vector("a5a5010b03090000000000000001076ac6", DEMOC_DEVICE_DEV_B,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"per_device\",\"device\":"
                 "\"dev_b\",\"values\":{\"b\":1,\"extra\":7}}]}\n");
}

TEST(Vectors, demo_per_device_dev_b_without_extra) {
    check_vector("a5a5010a030800000000000000ff5f46", DEMOC_DEVICE_DEV_B,
                 "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":3,\"name\":\"per_device\",\"device\":"
                 "\"dev_b\",\"values\":{\"b\":255}}]}\n");
}

TEST(Vectors, demo_sample_repeated) {
    check_vector(
        "a5a5903e011d3f8000000000000000000000000000000102030405060708fe3f000000011d0000000000000000000000003f"
        "80000000000000000000007fbf800000f1a4",
        DEMOC_DEVICE_ANY,
        "{\"offset\":0,\"set\":144,\"fields\":[{\"descriptor\":1,\"name\":\"sample\",\"values\":{\"quat\":[1."
        "0,0.0,0.0,0.0],\"big\":72623859790382856,\"small\":-2,\"f\":0.5}},{\"descriptor\":1,\"name\":"
        "\"sample\",\"values\":{\"quat\":[0.0,0.0,0.0,1.0],\"big\":0,\"small\":127,\"f\":-1.0}}]}\n");
}

TEST(Vectors, demo_receiver_1_shared_and_layout) {
    check_vector("a5a5911ed308000000003b9aca0003124046c00000000000c05e90000000000000037f56", DEMOC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":145,\"fields\":[{\"descriptor\":211,\"name\":\"timestamp\","
                 "\"values\":{\"nanoseconds\":1000000000}},{\"descriptor\":3,\"name\":\"llh_position\","
                 "\"values\":{\"latitude\":45.5,\"longitude\":-122.25,\"valid_flags\":3}}]}\n");
}

TEST(Vectors, demo_receiver_2_same_layout) {
    check_vector("a5a5921403124046c00000000000c05e9000000000000003fc84", DEMOC_DEVICE_ANY,
                 "{\"offset\":0,\"set\":146,\"fields\":[{\"descriptor\":3,\"name\":\"llh_position\","
                 "\"values\":{\"latitude\":45.5,\"longitude\":-122.25,\"valid_flags\":3}}]}\n");
}

TEST(Vectors, demo_ping_bad_checksum) {
    check_vector("a5a5010201004f23", DEMOC_DEVICE_ANY, "{\"offset\":0,\"skipped\":\"a5a5010201004f23\"}\n");
}
