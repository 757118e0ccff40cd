/* configure_and_stream ADDRESS [COUNT]: configures a ms_imu3020 with mscipcodec's command session and prints
 * COUNT data packets (default 5).
 *
 * ADDRESS is tcp:HOST:PORT or a serial device path (opened at 115200 baud). The program pings the
 * device, reads its get device model, writes then reads one setting (IMU sample rate configure), sets the
 * data message (Select sensors (Rev A)), enables the stream (Data on/off) and prints the
 * fields of IMU Data Message (0xA2) through one handler per data descriptor. A NACK, a
 * timeout or a refused command ends it with a message and exit status 1.
 *
 * The documentation quotes the parts between the [...] and [end] comments. Generated: do not edit. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mscipcodec/mscipcodec.h"
#include "mscipcodec/posix_transport.h"

#define WAIT_MS 5000u /* how long to wait for the data packets */

/* Reports a command that did not succeed (a NACK with its code, a timeout, a refusal) and
 * returns the exit status 1. */
static int failed(const char *command, const mscipc_link_t *link) {
    fprintf(stderr, "configure_and_stream: %s: %s", command, mscipc_result_kind_name(link->result.kind));
    if (link->result.kind == MSCIPC_RESULT_NACK) {
        fprintf(stderr, " (code %lu)", (unsigned long)link->result.code);
    }
    if (link->result.error[0] != '\0') {
        fprintf(stderr, ": %s", link->result.error);
    }
    fprintf(stderr, "\n");
    return 1;
}

static int configure(mscipc_link_t *link) {
    mscipc_imu_config_sample_rate_response_t setting;
    // [configure]
    if (mscipc_imu_config_sample_rate_write(link, 10) != MSCIPC_RESULT_ACK) {
        return failed("imu_config.sample_rate write", link);
    }
    if (mscipc_imu_config_sample_rate_read(link, &setting) != MSCIPC_RESULT_ACK) {
        return failed("imu_config.sample_rate read", link);
    }
    printf("setting decimation=%llu\n", (unsigned long long)setting.decimation);
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
static void on_packet(void *ctx, const mscipc_event_t *packet) {
    stream_t *stream = (stream_t *)ctx;
    if (mscipc_packet_set(packet->packet) == 0xA2) {
        stream->packets++;
    }
}

static void on_scaled_accel(void *ctx, const mscipc_field_value_t *value, const mscipc_event_t *packet) {
    const stream_t *stream = (const stream_t *)ctx;
    const mscipc_imu_data_scaled_accel_t *v = &value->u.imu_data_scaled_accel;
    (void)packet;
    if (stream->packets <= stream->count) { /* on_packet has counted this packet */
        printf("scaled_accel accel=[%g, %g, %g]\n", (double)v->accel[0], (double)v->accel[1],
               (double)v->accel[2]);
    }
}

static void on_scaled_gyro(void *ctx, const mscipc_field_value_t *value, const mscipc_event_t *packet) {
    const stream_t *stream = (const stream_t *)ctx;
    const mscipc_imu_data_scaled_gyro_t *v = &value->u.imu_data_scaled_gyro;
    (void)packet;
    if (stream->packets <= stream->count) { /* on_packet has counted this packet */
        printf("scaled_gyro gyro=[%g, %g, %g]\n", (double)v->gyro[0], (double)v->gyro[1], (double)v->gyro[2]);
    }
}

static int stream(mscipc_link_t *link, unsigned count) {
    static stream_t stream; /* the handlers use it while the link is open */
    uint64_t now, deadline;
    static const mscipc_sensor_code_t sensors[] = {MSCIPC_SENSOR_CODE_SCALED_ACCEL,
                                                   MSCIPC_SENSOR_CODE_SCALED_GYRO};
    stream.packets = 0;
    stream.count = count;
    mscipc_session_on_packet(&link->session, on_packet, &stream);
    if (mscipc_session_on_field(&link->session, 0xA2, 0x81, on_scaled_accel, &stream) != MSCIPC_OK) {
        fprintf(stderr, "configure_and_stream: too many field handlers\n");
        return 1;
    }
    if (mscipc_session_on_field(&link->session, 0xA2, 0x82, on_scaled_gyro, &stream) != MSCIPC_OK) {
        fprintf(stderr, "configure_and_stream: too many field handlers\n");
        return 1;
    }
    if (mscipc_imu_config_select_sensors_write(link, 0, sensors, 2u) != MSCIPC_RESULT_ACK) {
        return failed("imu_config.select_sensors write", link);
    }
    if (mscipc_imu_config_data_on_off_write(link, MSCIPC_ON_OFF_ON) != MSCIPC_RESULT_ACK) {
        return failed("imu_config.data_on_off write", link);
    }
    now = link->transport.now_ms(link->transport.ctx);
    deadline = now + WAIT_MS;
    while (stream.packets < count && now < deadline) {
        if (mscipc_link_pump(link, (uint32_t)(deadline - now)) < 0) { /* data packets reach the handlers */
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
    static mscipc_link_t link; /* holds the receive buffers: not on the stack */
    mscipc_posix_t port;
    mscipc_transport_t transport;
    mscipc_session_config_t config;
    mscipc_base_device_model_t info;
    unsigned count = 5u;
    int status;
    if ((argc != 2 && argc != 3) || (argc == 3 && !parse_count(argv[2], &count))) {
        fprintf(stderr, "usage: configure_and_stream ADDRESS [COUNT]\n");
        return 2;
    }
    // [connect]
    if (mscipc_posix_open(&port, argv[1], 115200) != MSCIPC_OK) { /* tcp:HOST:PORT or a serial port path */
        fprintf(stderr, "configure_and_stream: %s\n", port.error);
        return 1;
    }
    mscipc_posix_transport(&port, &transport);
    mscipc_session_config_init(&config);
    config.device = MSCIPC_DEVICE_MS_IMU3020; /* commands this model does not support are refused, not sent */
    if (mscipc_link_init(&link, &transport, &config) != MSCIPC_OK) {
        fprintf(stderr, "configure_and_stream: cannot start the session\n");
        mscipc_posix_close(&port);
        return 1;
    }
    if (mscipc_base_ping(&link) != MSCIPC_RESULT_ACK) {
        status = failed("base.ping", &link);
    } else if (mscipc_base_get_device_model(&link, &info) != MSCIPC_RESULT_ACK) {
        status = failed("base.get_device_model", &link);
    } else {
        printf("device model=\"%.*s\"\n", (int)sizeof info.model, info.model);
        // [end]
        status = configure(&link);
        if (status == 0) {
            status = stream(&link, count);
        }
    }
    mscipc_link_close(&link);
    mscipc_posix_close(&port);
    return status;
}
