// The session corpus (tests/sessions/mscip/, docs/conformance.md section 8) as a table for
// tests/session_test.cpp. Generated: do not edit.
#pragma once

#include <vector>

#include "mscipcodec/mscipcodec.h"

namespace session_cases {

struct Step {
    unsigned at;
    const char *send;    // a command line, or nullptr
    const char *bytes;   // the packet the command must send (hex), or nullptr
    const char *receive; // the bytes received (hex), or nullptr
};

struct Case {
    const char *name;
    mscipc_device_t device;
    unsigned timeout_ms;
    unsigned inter_packet_timeout_ms;
    std::vector<Step> steps;
    const char *expect; // the lines, each ending with a newline
};

inline const std::vector<Case> &cases() {
    static const std::vector<Case> all = {
        {"ping_ack",
         MSCIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              "a5a5010202004f25", nullptr},
             {5, nullptr, nullptr, "a5a5010480020200d3cf"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}\n"},
        {"reply_with_data_field",
         MSCIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\","
              "\"values\":{}}]}",
              "a5a501020500522b", nullptr},
             {5, nullptr, nullptr, "a5a501168002050085102020202020204d535f494d5533303230ec54"},
         },
         "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":133,\"name\":\"device_model\","
         "\"values\":{\"model\":\"      MS_IMU3020\"}}]}\n"},
        {"nack_with_every_error_code",
         MSCIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {1, nullptr, nullptr, "a5a5010480020201d4d0"},
             {1, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {2, nullptr, nullptr, "a5a5010480020202d5d1"},
             {2, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {3, nullptr, nullptr, "a5a5010480020203d6d2"},
             {3, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {4, nullptr, nullptr, "a5a5010480020204d7d3"},
         },
         "{\"line\":1,\"result\":\"nack\",\"code\":1,\"reply\":[]}\n{\"line\":2,\"result\":\"nack\",\"code\":"
         "2,\"reply\":[]}\n{\"line\":3,\"result\":\"nack\",\"code\":3,\"reply\":[]}\n{\"line\":4,\"result\":"
         "\"nack\",\"code\":4,\"reply\":[]}\n"},
        {"data_garbage_and_another_reply_before_the_answer",
         MSCIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {2, nullptr, nullptr, "00a501a5a5a20e810c37a7c5ac377ba8823f800065d61a"},
             {3, nullptr, nullptr, "a5a5020480020200d4d5"},
             {4, nullptr, nullptr, "a5a5010480020200d3cf"},
         },
         "{\"offset\":0,\"skipped\":\"00a501\"}\n{\"offset\":3,\"set\":162,\"fields\":[{\"descriptor\":129,"
         "\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1."
         "0000120401382446]}}]}\n{\"offset\":23,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\","
         "\"values\":{\"command_code\":2,\"error_code\":0}}]}\n{\"line\":1,\"result\":\"ack\",\"code\":0,"
         "\"reply\":[]}\n"},
        {"reply_field_that_does_not_decode",
         MSCIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0,
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\","
              "\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "a5a5010a80020500850420202020e58d"},
         },
         "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[{\"descriptor\":133,\"data\":\"20202020\","
         "\"error\":\"model: needs 16 bytes at offset 0, 4 left\"}],\"error\":\"model: needs 16 bytes at "
         "offset 0, 4 left\"}\n"},
        {"late_reply_after_a_timeout",
         MSCIPC_DEVICE_ANY,
         150,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {150,
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\","
              "\"values\":{}}]}",
              nullptr, nullptr},
             {200, nullptr, nullptr, "a5a5010480020200d3cf"},
             {210, nullptr, nullptr, "a5a501168002050085102020202020204d535f494d5533303230ec54"},
         },
         "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}\n{\"offset\":0,\"set\":1,\"fields\":"
         "[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}\n{"
         "\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":133,\"name\":\"device_model\","
         "\"values\":{\"model\":\"      MS_IMU3020\"}}]}\n"},
        {"false_sync_dropped_by_the_timed_rule",
         MSCIPC_DEVICE_ANY,
         1000,
         100,
         {
             {0, "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}",
              nullptr, nullptr},
             {5, nullptr, nullptr, "a5a501f0a5a5010480020200d3cf"},
         },
         "{\"offset\":0,\"skipped\":\"a5a501f0\"}\n{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}"
         "\n"},
    };
    return all;
}

} // namespace session_cases
