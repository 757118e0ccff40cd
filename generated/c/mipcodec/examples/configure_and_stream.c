/* configure_and_stream ADDRESS [COUNT]: configures a cv7_ins with mipcodec's command session and prints
 * COUNT data packets (default 5).
 *
 * ADDRESS is tcp:HOST:PORT or a serial device path (opened at 115200 baud). The program pings the
 * device, reads its get device information, writes then reads one setting (Sensor-to-vehicle frame
 * transformation (Euler)), sets the data message (Message format), enables the stream (Data stream control)
 * and prints the fields of Sensor (IMU) Data Set (0x80) through one handler per data descriptor. A NACK, a
 * timeout or a refused command ends it with a message and exit status 1.
 *
 * The documentation quotes the parts between the [...] and [end] comments. Generated: do not edit. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mipcodec/mipcodec.h"
#include "mipcodec/posix_transport.h"

#define WAIT_MS 5000u /* how long to wait for the data packets */

/* Reports a command that did not succeed (a NACK with its code, a timeout, a refusal) and
 * returns the exit status 1. */
static int failed(const char *command, const mipc_link_t *link) {
    fprintf(stderr, "configure_and_stream: %s: %s", command, mipc_result_kind_name(link->result.kind));
    if (link->result.kind == MIPC_RESULT_NACK) {
        fprintf(stderr, " (code %lu)", (unsigned long)link->result.code);
    }
    if (link->result.error[0] != '\0') {
        fprintf(stderr, ": %s", link->result.error);
    }
    fprintf(stderr, "\n");
    return 1;
}

static int configure(mipc_link_t *link) {
    mipc_threedm_sensor_to_vehicle_euler_response_t setting;
    // [configure]
    if (mipc_threedm_sensor_to_vehicle_euler_write(link, 0.0f, 0.0f, 1.5f) != MIPC_RESULT_ACK) {
        return failed("threedm.sensor_to_vehicle_euler write", link);
    }
    if (mipc_threedm_sensor_to_vehicle_euler_read(link, &setting) != MIPC_RESULT_ACK) {
        return failed("threedm.sensor_to_vehicle_euler read", link);
    }
    printf("setting roll=%g pitch=%g yaw=%g\n", (double)setting.roll, (double)setting.pitch,
           (double)setting.yaw);
    // [end]
    return 0;
}

// [stream]
/* The data packets received, and how many to print. */
typedef struct {
    unsigned packets;
    unsigned count;
} stream_t;

/* Every packet that is not a reply: counts the data packets (it runs before the field handlers). */
static void on_packet(void *ctx, const mipc_event_t *packet) {
    stream_t *stream = (stream_t *)ctx;
    if (mipc_packet_set(packet->packet) == 0x80) {
        stream->packets++;
    }
}

static void on_scaled_accel(void *ctx, const mipc_field_value_t *value, const mipc_event_t *packet) {
    const stream_t *stream = (const stream_t *)ctx;
    const mipc_sensor_scaled_accel_t *v = &value->u.sensor_scaled_accel;
    (void)packet;
    if (stream->packets <= stream->count) { /* on_packet has counted this packet */
        printf("scaled_accel scaled_accel=[%g, %g, %g]\n", (double)v->scaled_accel[0],
               (double)v->scaled_accel[1], (double)v->scaled_accel[2]);
    }
}

static void on_scaled_gyro(void *ctx, const mipc_field_value_t *value, const mipc_event_t *packet) {
    const stream_t *stream = (const stream_t *)ctx;
    const mipc_sensor_scaled_gyro_t *v = &value->u.sensor_scaled_gyro;
    (void)packet;
    if (stream->packets <= stream->count) { /* on_packet has counted this packet */
        printf("scaled_gyro scaled_gyro=[%g, %g, %g]\n", (double)v->scaled_gyro[0], (double)v->scaled_gyro[1],
               (double)v->scaled_gyro[2]);
    }
}

static int stream(mipc_link_t *link, unsigned count) {
    static stream_t stream; /* the handlers use it while the link is open */
    uint64_t now, deadline;
    static const mipc_descriptor_rate_t descriptors[] = {{.descriptor = 4, .decimation = 100},
                                                         {.descriptor = 5, .decimation = 100}};
    stream.packets = 0;
    stream.count = count;
    mipc_session_on_packet(&link->session, on_packet, &stream);
    if (mipc_session_on_field(&link->session, 0x80, 0x04, on_scaled_accel, &stream) != MIPC_OK) {
        fprintf(stderr, "configure_and_stream: too many field handlers\n");
        return 1;
    }
    if (mipc_session_on_field(&link->session, 0x80, 0x05, on_scaled_gyro, &stream) != MIPC_OK) {
        fprintf(stderr, "configure_and_stream: too many field handlers\n");
        return 1;
    }
    if (mipc_threedm_message_format_write(link, 0x80, descriptors, 2u) != MIPC_RESULT_ACK) {
        return failed("threedm.message_format write", link);
    }
    if (mipc_threedm_data_stream_control_write_cv7_ins(link, 0x80, true) != MIPC_RESULT_ACK) {
        return failed("threedm.data_stream_control write", link);
    }
    now = link->transport.now_ms(link->transport.ctx);
    deadline = now + WAIT_MS;
    while (stream.packets < count && now < deadline) {
        if (mipc_link_pump(link, (uint32_t)(deadline - now)) < 0) { /* data packets reach the handlers */
            fprintf(stderr, "configure_and_stream: the connection failed\n");
            return 1;
        }
        now = link->transport.now_ms(link->transport.ctx);
    }
    // [end]
    if (stream.packets < count) {
        fprintf(stderr, "configure_and_stream: %u of %u data packets in %u ms\n", stream.packets, count,
                WAIT_MS);
        return 1;
    }
    return 0;
}

/* COUNT: a decimal number of packets, at least 1. */
static bool parse_count(const char *text, unsigned *count) {
    char *end;
    unsigned long n;
    if (text[0] < '0' || text[0] > '9') {
        return false;
    }
    n = strtoul(text, &end, 10);
    if (*end != '\0' || n == 0 || n > 1000000ul) {
        return false;
    }
    *count = (unsigned)n;
    return true;
}

int main(int argc, char **argv) {
    static mipc_link_t link; /* holds the receive buffers: not on the stack */
    mipc_posix_t port;
    mipc_transport_t transport;
    mipc_session_config_t config;
    mipc_base_device_info_t info;
    unsigned count = 5u;
    int status;
    if ((argc != 2 && argc != 3) || (argc == 3 && !parse_count(argv[2], &count))) {
        fprintf(stderr, "usage: configure_and_stream ADDRESS [COUNT]\n");
        return 2;
    }
    // [connect]
    if (mipc_posix_open(&port, argv[1], 115200) != MIPC_OK) { /* tcp:HOST:PORT or a serial port path */
        fprintf(stderr, "configure_and_stream: %s\n", port.error);
        return 1;
    }
    mipc_posix_transport(&port, &transport);
    mipc_session_config_init(&config);
    config.device = MIPC_DEVICE_CV7_INS; /* commands this model does not support are refused, not sent */
    if (mipc_link_init(&link, &transport, &config) != MIPC_OK) {
        fprintf(stderr, "configure_and_stream: cannot start the session\n");
        mipc_posix_close(&port);
        return 1;
    }
    if (mipc_base_ping(&link) != MIPC_RESULT_ACK) {
        status = failed("base.ping", &link);
    } else if (mipc_base_get_device_info(&link, &info) != MIPC_RESULT_ACK) {
        status = failed("base.get_device_info", &link);
    } else {
        printf("device info.firmware_version=%llu info.model_name=\"%.*s\" info.model_number=\"%.*s\" "
               "info.serial_number=\"%.*s\" info.lot_number=\"%.*s\" info.device_options=\"%.*s\"\n",
               (unsigned long long)info.info.firmware_version, (int)sizeof info.info.model_name,
               info.info.model_name, (int)sizeof info.info.model_number, info.info.model_number,
               (int)sizeof info.info.serial_number, info.info.serial_number, (int)sizeof info.info.lot_number,
               info.info.lot_number, (int)sizeof info.info.device_options, info.info.device_options);
        // [end]
        status = configure(&link);
        if (status == 0) {
            status = stream(&link, count);
        }
    }
    mipc_link_close(&link);
    mipc_posix_close(&port);
    return status;
}
