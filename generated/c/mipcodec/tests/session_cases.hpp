// The session corpus (tests/sessions/mip/, docs/conformance.md section 8) as a table for
// tests/session_test.cpp. Generated: do not edit.
#pragma once

#include <vector>

#include "mipcodec/mipcodec.h"

namespace session_cases {

struct Step {
    unsigned at;
    const char *send;    // a command line, or nullptr
    const char *bytes;   // the packet the command must send (hex), or nullptr
    const char *receive; // the bytes received (hex), or nullptr
};

struct Case {
    const char *name;
    mipc_device_t device;
    unsigned timeout_ms;
    unsigned inter_packet_timeout_ms;
    std::vector<Step> steps;
    const char *expect; // the lines, each ending with a newline
};

inline const std::vector<Case> &cases() {
    static const std::vector<Case> all = {
        {"ping_ack",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              "756501020201e0c6", nullptr},
             {5, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"read_with_reply_field",
         MIPC_DEVICE_CV7_INS,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":2}}]}",
              "75650c030331021f46", nullptr},
             {7, nullptr, nullptr, "75650c1204f131000eb1000000003fc90ff93fc90ff9fdd3"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":177,\"name\":\"sensor_to_"
         "vehicle_euler_response\",\"values\":{\"roll\":0.0,\"pitch\":1.5707999467849731,\"yaw\":1."
         "5707999467849731}}]}\n"},
        {"write_then_read",
         MIPC_DEVICE_CV7_INS,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":1,\"roll\":0.0,\"pitch\":1.5707999467849731,\"yaw\":1."
              "5707999467849731}}]}",
              "75650c0f0f3101000000003fc90ff93fc90ff9563d", nullptr},
             {4, nullptr, nullptr, "75650c0404f13100100c"},
             {4,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":2}}]}",
              nullptr, nullptr},
             {9, nullptr, nullptr, "75650c1204f131000eb1000000003fc90ff93fc90ff9fdd3"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n{\"line\":2,\"result\":\"ack\",\"code\":0,"
         "\"reply\":[{\"descriptor\":177,\"name\":\"sensor_to_vehicle_euler_response\",\"values\":{\"roll\":"
         "0.0,\"pitch\":1.5707999467849731,\"yaw\":1.5707999467849731}}]}\n"},
        {"garbage_and_data_around_the_reply",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, nullptr, nullptr, "00117522"},
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {2, nullptr, nullptr, "7565800e0e040000000000000000bf800000b935aa"},
             {4, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"offset\":0,\"skipped\":\"00117522\"}\n{\"offset\":4,\"set\":128,\"fields\":[{\"descriptor\":4,"
         "\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.0,0.0,-1.0]}}]}\n{\"offset\":24,"
         "\"skipped\":\"aa\"}\n{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"reply_for_another_command",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "7565010404f10200d66c"},
             {4, nullptr, nullptr, "75650c0404f10100e0ac"},
             {5, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{"
         "\"command_descriptor\":2,\"ack_code\":0}}]}\n{\"offset\":10,\"set\":12,\"fields\":[{\"descriptor\":"
         "241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}\n{\"line\":1,"
         "\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"late_reply_after_a_timeout",
         MIPC_DEVICE_ANY,
         200,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {200,
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]"
              "}",
              "756501020202e1c7", nullptr},
             {250, nullptr, nullptr, "7565010404f10100d56a"},
             {260, nullptr, nullptr, "7565010404f10200d66c"},
         },
         "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}\n{\"offset\":0,\"set\":1,\"fields\":"
         "[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}"
         "\n{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"nack_with_every_code",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {1, nullptr, nullptr, "7565010404f10101d66b"},
             {1, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {2, nullptr, nullptr, "7565010404f10102d76c"},
             {2, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "7565010404f10103d86d"},
             {3, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {4, nullptr, nullptr, "7565010404f10104d96e"},
             {4, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "7565010404f10105da6f"},
             {5, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {6, nullptr, nullptr, "7565010404f10106db70"},
             {6, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {7, nullptr, nullptr, "7565010404f1017f54e9"},
         },
         "{\"line\":1,\"result\":\"nack\",\"code\":1,\"reply\":[]}\n{\"line\":2,\"result\":\"nack\",\"code\":"
         "2,\"reply\":[]}\n{\"line\":3,\"result\":\"nack\",\"code\":3,\"reply\":[]}\n{\"line\":4,\"result\":"
         "\"nack\",\"code\":4,\"reply\":[]}\n{\"line\":5,\"result\":\"nack\",\"code\":5,\"reply\":[]}\n{"
         "\"line\":6,\"result\":\"nack\",\"code\":6,\"reply\":[]}\n{\"line\":7,\"result\":\"nack\",\"code\":"
         "127,\"reply\":[]}\n"},
        {"nack_of_a_read",
         MIPC_DEVICE_CV7_INS,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":2}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "75650c0404f13103130f"},
         },
         "{\"line\":1,\"result\":\"nack\",\"code\":3,\"reply\":[]}\n"},
        {"ack_suppressed_by_function",
         MIPC_DEVICE_GX5_45,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":55,\"name\":\"accel_bias\",\"device\":"
              "\"gx5_45\",\"values\":{\"function\":6,\"bias\":[1.0,2.0,3.0]}}]}",
              "75650c0f0f37063f8000004000000040400000c0ea", nullptr},
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"line\":1,\"result\":\"sent\",\"code\":null,\"reply\":[]}\n{\"line\":2,\"result\":\"ack\","
         "\"code\":0,\"reply\":[]}\n"},
        {"ack_suppressed_by_parameter",
         MIPC_DEVICE_GX5_45,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":1,\"name\":\"poll_imu_data\",\"values\":{"
              "\"option\":1,\"num_descriptors\":0,\"descriptors\":[]}}]}",
              "75650c0404010100f0dc", nullptr},
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "7565800e0e040000000000000000bf800000b935"},
             {5, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"line\":1,\"result\":\"sent\",\"code\":null,\"reply\":[]}\n{\"offset\":0,\"set\":128,\"fields\":["
         "{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.0,0.0,-1.0]}}]}\n{"
         "\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"refused_command_for_the_device",
         MIPC_DEVICE_GX5_45,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":2}}]}",
              nullptr, nullptr},
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"line\":1,\"result\":\"refused\",\"code\":null,\"reply\":[],\"error\":\"sensor_to_vehicle_euler "
         "is not supported by 3DM-GX5-45 "
         "(3dm-gx5-45-dcp.txt)\"}\n{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"refused_function_for_the_device",
         MIPC_DEVICE_CV7_INS,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\","
              "\"device\":\"cv7_ins\",\"values\":{\"function\":2}}]}",
              nullptr, nullptr},
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\","
              "\"device\":\"cv7_ins\",\"values\":{\"function\":3}}]}",
              "75650c030330031f45", nullptr},
             {20, nullptr, nullptr, "75650c0404f130000f0a"},
         },
         "{\"line\":1,\"result\":\"refused\",\"code\":null,\"reply\":[],\"error\":\"function read of "
         "device_startup_settings is not supported by 3DM-CV7-GNSS/INS "
         "(3dm-cv7-ins-docs.txt)\"}\n{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"reply_field_that_does_not_decode",
         MIPC_DEVICE_CV7_INS,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":2}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "75650c0e04f131000ab1000000003fc90ff9e54d"},
         },
         "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[{\"descriptor\":177,\"data\":"
         "\"000000003fc90ff9\",\"error\":\"yaw: needs 4 bytes at offset 8, 0 left\"}],\"error\":\"yaw: needs "
         "4 bytes at offset 8, 0 left\"}\n"},
        {"bad_field_header_after_the_ack",
         MIPC_DEVICE_CV7_INS,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":2}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "75650c0604f1310001b1c4ed"},
         },
         "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[{\"trailing\":\"01b1\",\"error\":\"field "
         "length 1 at payload offset 4 is shorter than the field header\"}],\"error\":\"field length 1 at "
         "payload offset 4 is shorter than the field header\"}\n"},
        {"reply_field_missing",
         MIPC_DEVICE_CV7_INS,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\","
              "\"values\":{\"function\":2}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "75650c0404f13100100c"},
         },
         "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[],\"error\":\"missing reply field "
         "177\"}\n"},
        {"long_command_allowance",
         MIPC_DEVICE_CV7_INS,
         300,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":57,\"name\":\"capture_gyro_bias\","
              "\"values\":{\"averaging_time_ms\":1000}}]}",
              "75650c04043903e81270", nullptr},
             {1100, nullptr, nullptr, "75650c1204f139000e9b3a83126f00000000ba83126fcb11"},
             {1100,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\","
              "\"device\":\"cv7_ins\",\"values\":{\"function\":3}}]}",
              nullptr, nullptr},
             {2000, nullptr, nullptr, "75650c0404f130000f0a"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":155,\"name\":\"gyro_bias_"
         "response\",\"values\":{\"bias\":[0.0010000000474974513,0.0,-0.0010000000474974513]}}]}\n{\"line\":"
         "2,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"timeout_without_allowance",
         MIPC_DEVICE_CV7_INS,
         300,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":57,\"name\":\"capture_gyro_bias\","
              "\"values\":{\"averaging_time_ms\":1000}}]}",
              nullptr, nullptr},
             {1500, nullptr, nullptr, "75650c1204f139000e9b3a83126f00000000ba83126fcb11"},
         },
         "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}\n{\"offset\":0,\"set\":12,"
         "\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":57,\"ack_"
         "code\":0}},{\"descriptor\":155,\"name\":\"gyro_bias_response\",\"values\":{\"bias\":[0."
         "0010000000474974513,0.0,-0.0010000000474974513]}}]}\n"},
        {"false_sync_dropped_by_the_timed_rule",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "756501f07565010404f10100d56a"},
         },
         "{\"offset\":0,\"skipped\":\"756501f0\"}\n{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}"
         "\n"},
        {"false_sync_then_the_reply_later",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "756501f0"},
             {60, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"offset\":0,\"skipped\":\"756501f0\"}\n{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}"
         "\n"},
        {"slow_reply_kept_waiting",
         MIPC_DEVICE_ANY,
         500,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "7565010404"},
             {300, nullptr, nullptr, "f10100d56a"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"false_sync_then_the_reply_after_the_inter_packet_timeout",
         MIPC_DEVICE_ANY,
         500,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "756501f0"},
             {300, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"offset\":0,\"skipped\":\"756501f0\"}\n{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}"
         "\n"},
        {"false_sync_with_nothing_after_it_waits_for_close",
         MIPC_DEVICE_ANY,
         300,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "756501f0"},
         },
         "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}\n{\"offset\":0,\"skipped\":"
         "\"756501f0\"}\n"},
        {"reply_byte_by_byte_within_the_timeout",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "75"},
             {10, nullptr, nullptr, "65"},
             {15, nullptr, nullptr, "01"},
             {20, nullptr, nullptr, "04"},
             {25, nullptr, nullptr, "04"},
             {30, nullptr, nullptr, "f1"},
             {35, nullptr, nullptr, "01"},
             {40, nullptr, nullptr, "00"},
             {45, nullptr, nullptr, "d5"},
             {50, nullptr, nullptr, "6a"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"two_pending_answered_out_of_order",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {0,
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]"
              "}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "7565010404f10200d66c"},
             {4, nullptr, nullptr, "7565010404f10100d56a"},
         },
         "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n{\"line\":1,\"result\":\"ack\",\"code\":0,"
         "\"reply\":[]}\n"},
        {"one_packet_answers_two_commands",
         MIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {0,
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]"
              "}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "7565010804f1010004f10200d0c9"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n{\"line\":2,\"result\":\"ack\",\"code\":0,"
         "\"reply\":[]}\n"},
        {"same_command_twice_first_in_first_out",
         MIPC_DEVICE_ANY,
         50,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {10, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {20, nullptr, nullptr, "7565010404f10101d66b"},
         },
         "{\"line\":1,\"result\":\"nack\",\"code\":1,\"reply\":[]}\n{\"line\":2,\"result\":\"timeout\","
         "\"code\":null,\"reply\":[]}\n"},
    };
    return all;
}

} // namespace session_cases
