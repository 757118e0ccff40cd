// A C++ program that uses the mipcodec packages as their documentation says (docs/packaging.md),
// built by tests/consumer/test_consumers.py: the canonical JSON line of every packet and skip run
// of FILE through the C++ library, then the ping command built by the C library in the same
// program (linked only when CONSUMER_WITH_C is defined: the C and C++ packages fit one program).
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "mipcodec/mipcodec.hpp"
#ifdef CONSUMER_WITH_C
#include "mipcodec/mipcodec.h"
#endif

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: consumer FILE\n");
        return 2;
    }
    std::ifstream file(argv[1], std::ios::binary);
    const std::vector<std::uint8_t> input((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    mipcodec::decode_to_json_lines(input.data(), input.size(), 4096, std::nullopt,
                                   [](const std::string &line) { std::printf("%s\n", line.c_str()); });
#ifdef CONSUMER_WITH_C
    std::uint8_t packet[MIPC_MAX_PACKET];
    const std::uint8_t no_data[1] = {0};
    std::size_t len = 0;
    mipc_packet_builder_t builder;
    mipc_packet_begin(&builder, packet, sizeof packet, MIPC_BASE_SET);
    if (mipc_packet_add_field(&builder, MIPC_BASE_PING_DESCRIPTOR, no_data, 0) != MIPC_OK ||
        mipc_packet_finish(&builder, &len) != MIPC_OK) {
        return 1;
    }
    std::printf("command ");
    for (std::size_t i = 0; i < len; i++) {
        std::printf("%02x", packet[i]);
    }
    std::printf("\n");
#endif
    return 0;
}
