/* A C program on the session API of the mipcodec package (docs/packaging.md), built by
 * tests/consumer/test_consumers.py through pkg-config (mipcodec-posix) and through
 * find_package(mipcodec) (mipcodec::c_posix): connects to ADDRESS with the POSIX transport, pings
 * the device and prints "ping: " and the result's name (ack, nack, timeout, ...). Exit status 0 on
 * an ACK, 1 otherwise, 2 for a usage error. */
#include <stdio.h>

#include "mipcodec/mipcodec.h"
#include "mipcodec/posix_transport.h"

int main(int argc, char **argv) {
    static mipc_link_t link; /* holds the receive buffers: not on the stack */
    mipc_posix_t port;
    mipc_transport_t transport;
    mipc_session_config_t config;
    mipc_result_kind_t result;
    if (argc != 2) {
        fprintf(stderr, "usage: session ADDRESS\n");
        return 2;
    }
    if (mipc_posix_open(&port, argv[1], 115200) != MIPC_OK) {
        fprintf(stderr, "session: %s\n", port.error);
        return 1;
    }
    mipc_posix_transport(&port, &transport);
    mipc_session_config_init(&config);
    if (mipc_link_init(&link, &transport, &config) != MIPC_OK) {
        fprintf(stderr, "session: cannot start the session\n");
        mipc_posix_close(&port);
        return 1;
    }
    result = mipc_base_ping(&link);
    printf("ping: %s\n", mipc_result_kind_name(result));
    mipc_link_close(&link);
    mipc_posix_close(&port);
    return result == MIPC_RESULT_ACK ? 0 : 1;
}
